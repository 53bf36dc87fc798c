"""Constructions step by step (issue 14 item 6): the numbers against hand derivations.

Every reference below is worked out by hand from the thesis's definitions
(poles ``(-vy/ω, vx/ω)``, lines ``τ + y fx − x fy = 0``, the lever rule, the
centripetal force ``m l ω²`` toward the pole) or from an independent route (the
material acceleration of a joint point computed on both bodies).
"""
from __future__ import annotations

import xml.etree.ElementTree as ET

import re

import numpy as np
import pytest

from planargeo.draw.layout import legibility_problems
from planargeo.draw.render import figure
from planargeo.errors import InputError
from planargeo.scenes.construction import CONSTRUCTIONS, construct, parameters
from planargeo.widgets.construction import ConstructionExplorer

from _picture_checks import elements, problems


def steps_drawn(ex) -> list[int]:
    """The steps whose elements the picture draws (each element carries its step)."""
    return sorted({e["step"] for e in ex.picture()["elements"] if "step" in e})


def legible(ex) -> list[str]:
    """Problems of the picture: undescribed elements, labels on each other, as drawn by matplotlib too."""
    pic = ex.picture()
    return problems(pic) + legibility_problems(figure(pic))


def xy(p):
    return np.array([-p[1] / p[2], p[0] / p[2]])


def element(c, name):
    (e,) = [e for e in c.elements() if e.name == name]
    return e.value


# ------------------------------------------------------------------ the scene, by hand
def test_twist_sum_lever_rule_and_special_cases():
    c = construct("twist_sum", x1=0.0, y1=0.0, w1=1.0, x2=4.0, y2=0.0, w2=3.0)
    assert c.values["pole of v₃"] == pytest.approx((3.0, 0.0)) and c.values["β"] == 0.75
    assert [s.equation for s in c.steps] == ["4.10", "5.32", "4.11–4.13"]
    c = construct("twist_sum", x1=0.0, y1=0.0, w1=1.0, x2=2.0, y2=0.0, w2=-1.0)
    assert c.values["pole of v₃"] .startswith("at infinity (direction (") and c.steps[-1].equation == "4.13"
    assert c.case.startswith("opposite rotations")
    # ω = 2 about (0.5, 0) plus a translation 3 along x: P = Q + (u/ω) e⊥ = (0.5, 1.5) (4.16)
    c = construct("twist_sum", x1=0.5, y1=0.0, w1=2.0, w2=0.0, u2=3.0, angle2=0.0)
    assert c.values["ρ"] == 1.5 and c.values["pole of v₃"] == pytest.approx((0.5, 1.5))
    c = construct("twist_sum", x1=1.0, y1=1.0, x2=1.0, y2=1.0)
    assert c.case.startswith("coincident poles") and c.steps[1].elements == ()


def test_wrench_sum_concurrent_parallel_couple_shift():
    c = construct("wrench_sum", x1=-1.0, y1=0.0, F1=1.0, angle1=0.0, x2=2.0, y2=1.0, F2=2.0,
                  angle2=90.0)
    assert c.values["meet P"] == pytest.approx((2.0, 0.0))
    assert c.values["f₃"] == pytest.approx((1.0, 2.0, 4.0))      # moments 0 + 2·2 about O
    assert [s.id for s in c.steps] == ["lines", "meet", "parallelogram", "sum"]
    # the parallelogram's diagonal from P is f1 + f2
    (p, q) = element(c, "diag")
    assert q - p == pytest.approx([1.0, 2.0])
    # 1 N at x = -1 and 3 N at x = 3, both up: the lever rule puts the sum on x = 2 (4.43-4.45)
    c = construct("wrench_sum", x1=-1.0, y1=0.0, F1=1.0, angle1=90.0, x2=3.0, y2=0.0, F2=3.0,
                  angle2=90.0)
    f3 = element(c, "f3")
    assert c.values["β"] == 0.75 and f3[2] / f3[1] == pytest.approx(2.0)
    assert c.values["meet P"] .startswith("at infinity (direction (") and c.case.startswith("parallel forces")
    # equal and opposite: a couple -1·1 + 3·(-1) = -4 (4.4.2), drawn on no finite line
    c = construct("wrench_sum", x1=-1.0, y1=0.0, F1=1.0, angle1=90.0, x2=3.0, y2=0.0, F2=-1.0,
                  angle2=90.0)
    assert c.values["f₃"] == pytest.approx((0.0, 0.0, -4.0)) and "couple" in c.case
    # 2 N along x through O plus a couple 1: shifted by ρ = τ/F = 0.5 onto y = -0.5 (4.46)
    c = construct("wrench_sum", x1=0.0, y1=0.0, F1=2.0, angle1=0.0, F2=0.0, tau2=1.0)
    assert c.values["ρ"] == 0.5 and c.values["f₃"] == pytest.approx((2.0, 0.0, 1.0))
    (p, q) = element(c, "rho")
    assert q == pytest.approx([0.0, -0.5])


def test_velocity_kinematics_by_hand():
    c = construct("velocity", xv=0.0, yv=0.0, w=1.0, xj=3.0, yj=0.0, qd=2.0)
    assert c.values["pole of vᵢ"] == pytest.approx((2.0, 0.0))   # β k = 2/3 · 3 (4.48)
    assert c.values["ωᵢ"] == 3.0 and c.values["kᵢ"] == 3.0 and c.values["βᵢ"] == pytest.approx(2 / 3)


def test_acceleration_kinematics_by_hand_and_by_the_joint_point():
    c = construct("acceleration", xv=0.0, yv=0.0, w=1.0, xa=0.0, ya=0.0, alpha=0.0,
                  xj=2.0, yj=0.0, qd=1.0, qdd=1.0)
    # κ = v × s q̇ = (2, 0): a translation along the line from the pole to the joint,
    # |κ| = ω q̇ k = 1 · 1 · 2 (4.53); s q̈ + κ turns about the point ρ = 2 above the joint (4.54)
    assert element(c, "kappa") == pytest.approx([2.0, 0.0, 0.0])
    assert c.values["|κᵢ|"] == 2.0 and c.values["ρᵢ"] == 2.0
    assert c.values["pole of aᵢ"] == pytest.approx((2.0, 2.0))
    a = np.array(c.values["aᵢ"])
    # independent check: the joint point (2, 0) is a point of both bodies.  On body i-1 (steady
    # spin ω = 1 about O) its acceleration is -ω² r = (-2, 0).  On body i: the linear part of a_i
    # at the point plus ω_i × v_p with ω_i = 2 and v_p = (0, 2) must give the same.
    p = np.array([2.0, 0.0])
    lin = a[:2] + a[2] * np.array([-p[1], p[0]])
    vp = np.array([0.0, 2.0])
    material = lin + 2.0 * np.array([-vp[1], vp[0]])
    assert material == pytest.approx([-2.0, 0.0])
    assert [s.equation for s in c.steps] == ["4.52", "4.47", "4.52", "4.53", "4.54", "4.52"]


def test_newton_euler_and_rho_by_hand():
    # m 1 at O with ρ_g 0.5 (I = diag(1, 1, 0.25)); v: ω 1 about (0, 2); a: α 1 about (1, 0)
    c = construct("newton_euler", m=1.0, xc=0.0, yc=0.0, r=0.5, xv=0.0, yv=2.0, w=1.0,
                  xa=1.0, ya=0.0, alpha=1.0, xj=-0.75, yj=0.0)
    Ia, p, f = element(c, "Ia"), element(c, "p"), element(c, "fnet")
    # axis of percussion of a pole 1 right of the centre: the line x = -ρ²/d = -0.25 (5.67)
    assert Ia == pytest.approx([0.0, -1.0, 0.25])
    # the centripetal force m l ω² = 2 through the centre toward the pole (0, 2): up along x = 0
    assert p == pytest.approx([0.0, 2.0, 0.0])
    assert f == pytest.approx([0.0, 1.0, 0.25])          # 1 N up along x = 0.25
    # the joint (-0.75, 0) is 1 to the left of the line x = 0.25: τ = 1, ρ = τ/F = 1 (4.57)
    assert c.values["τ"] == pytest.approx(1.0) and c.values["ρ = τ/|fⁿᵉᵗ|"] == pytest.approx(1.0)
    (j, foot) = element(c, "rho")
    assert foot == pytest.approx([0.25, 0.0])


def test_bad_input_is_named():
    with pytest.raises(InputError, match="^ω₂ = 0 rad/s and u₂ = 0 m/s make v₂ the zero twist"):
        construct("twist_sum", w2=0.0, u2=0.0)
    with pytest.raises(InputError, match="kind must be one of"):
        construct("nothing")
    with pytest.raises(InputError, match="has no parameter 'q'"):
        construct("velocity", q=1.0)
    with pytest.raises(InputError, match="x1 must be a finite number"):
        construct("twist_sum", x1=float("nan"))
    with pytest.raises(InputError, match="m must be positive"):
        construct("newton_euler", m=0.0)


# ------------------------------------------------------------------ the explorer
@pytest.fixture
def ex():
    return ConstructionExplorer("twist_sum", display="agg", x1=0.0, y1=0.0, w1=1.0,
                                x2=4.0 - 1.0, y2=0.0, w2=3.0)


def test_step_slider_draws_one_step_more_without_recomputing(ex):
    n = ex.n_computes
    ex.set(step=1)
    assert ex.caption == "Step 1/3: Q₁, Q₂: the poles of v₁ and v₂ (4.10)"
    assert steps_drawn(ex) == [1] and set(elements(ex.picture())) >= {"Q1", "Q2"}
    assert elements(ex.picture())["caption"]["parts"][1]["text"] == ex.caption       # drawn, whole
    assert ex.readout_values["equation"] == "4.10"
    ex.set(step=3)
    assert steps_drawn(ex) == [1, 2, 3]
    assert "β = ω₂/(ω₁+ω₂) = 0.75" in ex.caption
    v3 = next(p for p in elements(ex.picture())["v3"]["parts"] if p["p"] == "mark")
    assert (v3["x"], v3["y"]) == pytest.approx((2.25, 0.0))      # β = 3/4 of the way from Q₁ to Q₂
    assert ex.n_computes == n                    # the step is a display control


def test_dragging_an_input_redoes_the_construction(ex):
    ex.drag("v₂", ex.handle_position("v₂"), (3.0, 1.0), steps=3)
    assert ex.readout_values["pole of v₃"] == pytest.approx((2.25, 0.75))
    w = ConstructionExplorer("wrench_sum", display="agg", x1=-1.0, y1=0.0, F1=1.0, angle1=0.0,
                             x2=2.0, y2=1.0, F2=2.0, angle2=90.0)
    assert w.handle_position("f₂ direction") == pytest.approx((2.0, 2.0))
    w.drag("f₂ direction", (2.0, 2.0), (3.0, 1.0), steps=4)          # turned parallel to f1
    assert w.message == "" and w.readout_values["meet P"] .startswith("at infinity (direction (")
    assert w.readout_values["case"] == "parallel forces (4.43)"


def test_a_refused_value_keeps_the_shown_construction(ex):
    good = dict(ex.readout_values)
    ex.set(w2=0.0)
    assert "make v₂ the zero twist" in ex.message
    assert ex.readout_values == good and ex.values["w2"] == 3.0


def test_layers_export_one_group_per_step(ex, tmp_path):
    ex.set(step=1)
    path = ex.export_layers(tmp_path / "layers.svg")
    root = ET.parse(path).getroot()
    ids = [g.get("id") for g in root.iter("{http://www.w3.org/2000/svg}g") if g.get("id", "").startswith("step-")]
    assert ids == ["step-1-poles", "step-2-lever", "step-3-sum"]
    assert ex.step_ids() == ids
    assert steps_drawn(ex) == [1]                                                 # view unchanged
    groups = {g.get("id"): g for g in root.iter("{http://www.w3.org/2000/svg}g")}
    inner = {g.get("id", "").split(":")[0] for g in groups["step-3-sum"].iter() if g.get("id")}
    assert "v3" in inner and "Q1" not in inner                                   # each step its own
    assert path.read_bytes() == ex.export_layers(tmp_path / "again.svg").read_bytes()


@pytest.mark.parametrize("kind", list(CONSTRUCTIONS))
def test_every_step_of_every_construction_is_legible(kind):
    e = ConstructionExplorer(kind, display="agg")
    assert e.n_steps == len(construct(kind).steps) and set(parameters(kind)) < set(e.controls)
    for k in range(1, e.n_steps + 1):
        e.set(step=k)
        assert e.message == ""
        assert legible(e) == [], (kind, k)


@pytest.mark.parametrize("kind, state", [
    ("twist_sum", dict(w2=-1.0)), ("twist_sum", dict(x2=-1.5, y2=0.0)),
    ("twist_sum", dict(w2=0.0, u2=2.0)), ("wrench_sum", dict(angle2=60.0)),
    ("wrench_sum", dict(F2=0.0, tau2=1.0)), ("acceleration", dict(qdd=0.0)),
    ("newton_euler", dict(w=0.0)),
])
def test_special_states_are_legible(kind, state):
    e = ConstructionExplorer(kind, display="agg", **state)
    assert e.message == ""
    assert legible(e) == []


def test_registered():
    from planargeo.widgets import EXPLORERS

    assert EXPLORERS["ConstructionExplorer"] == "construction"
    with pytest.raises(InputError, match="construction must be one of"):
        ConstructionExplorer("nothing", display="agg")


def test_a_pole_dragged_through_infinity(tmp_path):
    """10.2.4: the handle h crosses the horizon |h| = R = 2; v₂ = k [h_y, −h_x, 1 − |h|/R].

    By hand, with h = (t, 0) and k = 1.5: v₂ = 1.5 [0, −t, 1 − t/2], a rotation about
    (t / (1 − t/2), 0) — (6, 0) at t = 1.5, off to +∞ as t → 2, the translation (0, -3) at
    t = 2 exactly, back from −∞ beyond (−42, 0) at t = 2.1.  The sum with v₁ (ω 1 about
    (−1.5, −1)) moves continuously, and nothing is refused on the way.
    """
    e = ConstructionExplorer("through_infinity", display="agg")
    poles, sums = [], []
    for t in (1.5, 1.9, 2.0, 2.1, 2.5):
        e.drag("h", e.handle_position("h"), (t, 0.0), steps=1)
        assert e.message == "" and legible(e) == []
        poles.append(e.readout_values["pole of v₂"])
        sums.append(np.array(e.readout_values["v₃"]))
    assert poles[0] == pytest.approx((6.0, 0.0)) and poles[1][0] == pytest.approx(38.0)
    assert poles[2].startswith("at infinity (direction (") and poles[3][0] == pytest.approx(-42.0)
    v1 = np.array([-1.0, 1.5, 1.0])                          # ω [y, −x, 1] about (−1.5, −1)
    for t, s in zip((1.5, 1.9, 2.0, 2.1, 2.5), sums):
        assert s == pytest.approx(v1 + 1.5 * np.array([0.0, -t, 1 - t / 2]))
    names = []
    for t in (1.9, 2.0, 2.1):
        e.drag("h", e.handle_position("h"), (t, 0.0), steps=1)
        names.append(e.readout_values["v₂"].split(":")[0])
    assert names == ["rotation about a finite pole (4.10)", "pure translation",
                     "rotation about a finite pole (4.10)"]
    assert [s.equation for s in e.state["c"].steps][0] == "10.2.4"


def test_earlier_steps_faded_shown_or_hidden(ex):
    ex.set(step=2, earlier="hidden")
    assert steps_drawn(ex) == [2]
    ex.set(earlier="shown")
    assert steps_drawn(ex) == [1, 2]
    assert elements(ex.picture())["Q1"].get("opacity", 1.0) == 1.0
    ex.set(earlier="faded")
    assert elements(ex.picture())["Q1"].get("opacity", 1.0) < 1.0
    assert elements(ex.picture())["Q1Q2"].get("opacity", 1.0) == 1.0              # the step shown


# ---------------------------------------------------------------- issue 22: every construction offered
def test_the_menu_offers_every_construction_the_scene_knows():
    e = ConstructionExplorer(display="agg")
    offered = [v for _, v in e.controls["construction"].options]
    assert offered == list(CONSTRUCTIONS)
    for kind in CONSTRUCTIONS:
        e.set(construction=kind)
        assert e.message == "" and e.construction == kind
        # the shown construction is the scene's, with that construction's defaults
        assert e.state["c"].kind == kind and e.state["c"].params == parameters(kind)
        assert e.values["step"] == e.n_steps == len(construct(kind).steps) == e.controls["step"].max
        # the sliders it does not use are disabled with a reason (and hidden)
        off = e.disabled(e.values)
        for name in e.controls:
            if name in {n for k in CONSTRUCTIONS for n in parameters(k)} and name not in parameters(kind):
                assert "no such input" in off[name], (kind, name)
        # of its own, only those idle at its defaults (twist addition: no direction while u = 0)
        idle = {"twist_sum": {"angle1", "angle2"}}.get(kind, set())
        assert {n for n in parameters(kind) if n in off} == idle, (kind, off)
        assert all(k in e.explain() for k in e.readout_values), kind


def test_newton_euler_from_the_menu_matches_the_hand_derivation():
    # the same body as test_newton_euler_and_rho_by_hand, reached through the menu
    e = ConstructionExplorer(display="agg")
    e.set(construction="newton_euler")
    e.set(m=1.0, xc=0.0, yc=0.0, r=0.5, xv=0.0, yv=2.0, w=1.0, xa=1.0, ya=0.0, alpha=1.0,
          xj=-0.75, yj=0.0)
    assert e.message == ""
    assert e.readout_values["fⁿᵉᵗ"] == pytest.approx((0.0, 1.0, 0.25))
    assert e.readout_values["τ"] == pytest.approx(1.0)
    assert e.readout_strings["fⁿᵉᵗ"] == "(0 N, 1 N, 0.25 N·m)"       # one unit per component


def test_the_key_names_what_is_on_screen():
    """Issue 21: the key did nothing.  Now it lists the symbols drawn with their meanings."""
    def key(e):
        return " | ".join(p["text"] for el in e.picture()["elements"] if el["id"].startswith("key ")
                          for p in el["parts"] if p["p"] == "text")

    e = ConstructionExplorer("newton_euler", display="agg", key=True)
    text = key(e)
    for meaning in ("velocity pole v of the body", "acceleration pole a of the body", "net force",
                    "bias force p", "inertia I as its circle of gyration"):
        assert meaning in text, meaning
    e.set(step=1)                      # only the inertia is drawn: the key says only that
    assert "inertia I as its circle of gyration" in key(e) and "velocity pole" not in key(e)
    e.set(key=False)
    assert key(e) == ""


def test_sliders_say_symbols_and_units_not_code_names():
    e = ConstructionExplorer("acceleration", display="agg")
    shown = {k: w.description for k, w in e.controls.items() if k in parameters("acceleration")}
    assert shown["qdd"] == "q̈ᵢ (rad/s²)" and shown["alpha"] == "αᵢ₋₁ (rad/s²)"
    for text in shown.values():
        assert "_" not in text and "(" in text
    for k, v in e.readout_values.items():
        assert "_" not in k and not re.search(r"\b(qdd|qd|alpha|f_net|F_net)\b", k)


def test_a_fresh_explorer_from_the_values_shows_the_same_after_a_history():
    e = ConstructionExplorer(display="agg")
    e.set(construction="wrench_sum")
    e.drag("f₁", e.handle_position("f₁"), (0.5, 1.0), steps=2)
    e.set(step=2, earlier="hidden")
    fresh = ConstructionExplorer(display="agg", **e.values)
    assert fresh.readout_strings == e.readout_strings and fresh.caption == e.caption
    e.reset()
    assert e.values == ConstructionExplorer(display="agg").values
    assert e.construction == "twist_sum" and e.readout_values["step"] == "3/3"


def test_earlier_steps_control_is_disabled_at_step_one(ex):
    assert "earlier" not in ex.disabled(ex.values)
    ex.set(step=1)
    assert "step 1" in ex.disabled(ex.values)["earlier"]
    before = dict(ex.readout_values)
    shown = ex.picture()["elements"]
    ex.set(earlier="hidden")                    # indeed nothing changes: one step is shown
    assert ex.readout_values == before and ex.picture()["elements"] == shown


def test_a_line_of_the_construction_is_described_as_a_line_not_a_force():
    """A lever line joins two poles: its hover text gives its place (by hand), never a force's size."""
    def desc(e, name):
        (el,) = [el for el in e.picture()["elements"] if el["id"] == name]
        return el["desc"]

    # Q₁ = (0, 0), Q₂ = (3, 0): the lever line is the x axis, 0 m from the origin; through (0, 1), (3, 1)
    # it is 1 m from the origin
    e = ConstructionExplorer("twist_sum", display="agg", x1=0.0, y1=1.0, w1=1.0, x2=3.0, y2=1.0, w2=3.0)
    text = desc(e, "Q1Q2")
    assert "force" not in text and " N" not in text, text
    assert text.endswith("a line 1 m from the origin"), text
    e.set(construction="velocity")
    assert "force" not in desc(e, "lever") and "m from the origin" in desc(e, "lever")
    # a force's line still says its size: f₁ of 1 N at 60° through (1, 0) … by the wrench's own numbers
    e.set(construction="wrench_sum")
    assert desc(e, "f1").split(": ")[-1].startswith("|force| ")


@pytest.mark.parametrize("first", ["twist_sum", "wrench_sum"])
def test_a_new_construction_opens_with_every_step_and_the_page_shows_it(first):
    """Step 1, then every construction from the menu (as the page picks it): each opens with all of
    its steps, and the step slider equals the step drawn, in the kernel and in the page, whatever
    order the page applies an update's keys in."""
    from _page_slider import PageSlider

    e = ConstructionExplorer(first, display="agg")
    w = e.controls["step"]
    page = PageSlider(w)
    w.set_state({"value": 1})
    for kind in ["wrench_sum", "acceleration", "velocity", "newton_euler", "twist_sum", "through_infinity"]:
        if kind == e.construction:
            continue
        e.controls["construction"].set_state({"index": list(CONSTRUCTIONS).index(kind)})
        n = len(construct(kind).steps)
        assert e.construction == kind and (w.value, w.max) == (n, n)
        assert e.readout_values["step"] == f"{n}/{n}" and e.caption.startswith(f"Step {n}/{n}:")
        assert page.problems == [] and (page.shown["value"], page.shown["max"]) == (n, n), kind
