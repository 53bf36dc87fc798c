"""TreeExplorer: the closed loops hold (pin points share accelerations), forces pass the pins,
and the numbers shown match independent references (Lagrange multipliers in maximal coordinates,
dense CRBA, a hand count of the degrees of freedom)."""
import numpy as np
import pytest

from planargeo import scenes
from planargeo.algorithms.loops import constrained_dynamics_lagrange
from picture_checks import drawn_arrow, elements, overlapping_labels, parts, px_per_unit, shown_labels, undescribed
from planargeo.widgets.trees import TreeExplorer


def point_accel(a, p):
    """Acceleration of the body point at p from a spatial acceleration twist at rest (like 4.5)."""
    ax, ay, al = a
    return np.array([ax - al * p[1], ay + al * p[0]])


def pin_points(ex):
    pose = ex.state["sol"].data.pose
    return pose[:, :2] + np.column_stack([np.cos(pose[:, 2]), np.sin(pose[:, 2])])


@pytest.fixture
def ex():
    """The explorer; the state each test leaves it in must be legible (issue #13)."""
    e = TreeExplorer(display="agg", speed=0.0, gravity=9.81)             # the Fig 9.2 pose at rest under gravity
    yield e
    pic = e.picture()
    assert overlapping_labels(pic) + undescribed(pic) == []


def test_loops_close_at_rest(ex):
    a = ex.state["a"]
    tips = pin_points(ex)
    for i, j in ((3, 6), (7, 8)):
        assert tips[i] == pytest.approx(tips[j], abs=1e-12)
        assert point_accel(a[i], tips[i]) == pytest.approx(point_accel(a[j], tips[j]), abs=1e-9)


def test_degrees_of_freedom_hand_count(ex):
    # Fig 9.1: nine one-dof revolute joints; Fig 9.2 adds two pins, each fixing two
    # translations of one tip relative to another: 9 - 2 * 2 = 5.
    assert ex.readout_values["degrees of freedom"] == 9 - 2 * 2
    ex.controls["loops"].value = "open (Fig 9.1)"
    assert ex.readout_values["degrees of freedom"] == 9


@pytest.mark.parametrize("speed, mass, g", [(0.0, 1.0, 9.81), (1.5, 2.0, 4.0), (-2.0, 0.5, 0.0)])
def test_contact_forces_match_lagrange_reference(ex, speed, mass, g):
    ex.set(speed=speed, mass=mass, gravity=g)
    assert ex.message == ""
    # the reference: the scene's own state, solved by Lagrange multipliers in maximal coordinates
    res = scenes.build("constrained-tree", speed=speed, mass=mass, g=g)
    ref = constrained_dynamics_lagrange(res.model, res.state["q"], res.state["qd"], np.zeros(9))
    F = np.asarray(ref["F"]).reshape(-1, 3)
    for k, name in enumerate(("4-7", "8-9")):
        shown = ex.readout_values[f"|F{'₁₂'[k]}| (pin {name})"]
        assert shown == pytest.approx(np.hypot(F[k, 0], F[k, 1]), rel=1e-9, abs=1e-9)
        # the drawn wrench is the reference's, acting on body a: -F (9.61; same line, size)
        # the drawn force is the reference's, acting on body a: -F (9.61; same line, size), at 0.9 m for the
        # largest force of the picture
        pic = ex.picture()
        drawn = drawn_arrow(pic, f"F{'₁₂'[k]}")
        fmax = max(np.hypot(*x.wrench[:2]) for x in ex.state["reactions"])
        if drawn is None:                                   # shorter than 2 px: the line alone
            assert np.hypot(*F[k, :2]) * 0.9 / fmax * px_per_unit(pic) < 2.0
            continue
        vec, foot = drawn
        assert vec * fmax / 0.9 == pytest.approx(-F[k, :2], rel=1e-5, abs=1e-5 * fmax)
        assert np.dot([foot[1], -foot[0], 1.0], F[k]) == pytest.approx(0.0, abs=1e-4 * (1 + np.abs(F[k]).max()))
    assert ex.readout_values["q̈₁ (body 1)"] == pytest.approx(ref["qdd"][0], abs=1e-9)
    assert ex.readout_values["largest |q̈ᵢ|"] == pytest.approx(np.abs(ref["qdd"]).max(), rel=1e-9)


def test_open_tree_matches_pinocchio(ex):
    from bench import pinocchio_forward

    ex.set(loops="open (Fig 9.1)", speed=1.2, mass=1.5)
    res = scenes.build("tree", speed=1.2, mass=1.5)
    ref = pinocchio_forward(res.model, res.state["q"], res.state["qd"], np.zeros(9))
    assert ex.readout_values["q̈₁ (body 1)"] == pytest.approx(ref[0], abs=1e-10)
    assert ex.readout_values["largest |q̈ᵢ|"] == pytest.approx(np.abs(ref).max(), rel=1e-10)


def test_contact_forces_pass_through_the_pins(ex):
    tips = pin_points(ex)
    pic = ex.picture()
    for k, i in enumerate((3, 7)):
        F = ex.state["reactions"][9 + k].wrench
        x, y = tips[i]
        assert np.dot([y, -x, 1.0], F) == pytest.approx(0.0, abs=1e-9 * (1 + np.abs(F).max()))
        line = np.array(parts(elements(pic)[f"F{'₁₂'[k]}"], "path")[0]["xy"])   # drawn through the pin, along F
        assert np.mean(line, axis=0) == pytest.approx(tips[i], abs=1e-4)
        d = line[1] - line[0]
        assert d[0] * F[1] - d[1] * F[0] == pytest.approx(0.0, abs=1e-4 * np.hypot(*d) * np.hypot(*F[:2]))
    pins = parts(elements(pic)["pins"], "mark")
    np.testing.assert_allclose([(m["x"], m["y"]) for m in pins], [tips[3], tips[7]], atol=1e-4)


def test_opening_the_loops_changes_the_motion(ex):
    closed = dict(ex.readout_values)
    ex.controls["loops"].value = "open (Fig 9.1)"
    assert not {"F₁", "F₂", "pins"} & set(elements(ex.picture()))
    a = ex.state["a"]
    tips = pin_points(ex)
    assert not np.allclose(point_accel(a[3], tips[3]), point_accel(a[6], tips[6]))   # tips drift apart
    assert ex.readout_values["q̈₁ (body 1)"] != closed["q̈₁ (body 1)"]


def test_overlays_and_speed(ex):
    ex.set(speed=1.5, **{"velocity poles": True, "acceleration poles": True})
    els = elements(ex.picture())
    assert all(f"{k}{'₁₂₃₄₅₆₇₈₉'[i]}" in els for k in "va" for i in range(9))
    assert ex.message == ""


@pytest.mark.parametrize("toggle", ["velocity poles", "acceleration poles", "reaction forces"])
def test_display_toggles_do_not_recompute(toggle):
    ex = TreeExplorer(display="agg", speed=1.0)
    calls = []
    real = ex.compute
    ex.compute = lambda v, changed: calls.append(changed) or real(v, changed)
    before = ex.controls[toggle].value
    ex.controls[toggle].value = not before
    ex.controls[toggle].value = before
    ex.controls[toggle].value = not before
    assert calls == [] and ex.n_updates == 4
    ids = {"velocity poles": [f"v{s}" for s in "₁₂₃₄₅₆₇₈₉"], "acceleration poles": [f"a{s}" for s in "₁₂₃₄₅₆₇₈₉"],
           "reaction forces": [f"f{s}" for s in "₁₂₃₄₅₆₇₈₉"]}[toggle]
    els = elements(ex.picture())
    assert all((i in els) == (not before) for i in ids)
    # the picture still shows the state: the velocity poles are the joint-speed twists
    if toggle == "velocity poles":
        for i in range(9):
            v = ex.state["sol"].data.v[i]                 # [vx, vy, w]: the pole (-vy/w, vx/w)
            (m,) = parts(els[ids[i]], "mark") or [None]
            if m is not None:
                assert (m["x"], m["y"]) == pytest.approx((-v[1] / v[2], v[0] / v[2]), abs=1e-4)
    ex.controls["speed"].value = 0.5          # a physics control does recompute
    assert len(calls) == 1 and calls[0] == {"speed"}


def test_a_speed_change_runs_one_solve_and_no_direct_solution(ex):
    from test_widgets_path import calls_during

    def run(*changes):
        def action():
            for k, v in changes:
                ex.controls[k].value = v
        calls, _ = calls_during(action)
        # "direct": the 9.48 cross-check (the tree's articulated mobilities), from whichever caller
        return {name: sum(n for (caller, *called), n in calls.items() if called == [f"planargeo.{mod}", fn]
                          and (name == "direct" or caller in ("planargeo.widgets.trees", "planargeo.scenes.trees")))
                for name, mod, fn in (("direct", "algorithms.articulated_mobility", "mobility_recursion"),
                                      ("model", "scenes.trees", "tree_model"),
                                      ("loop", "algorithms.loops", "loop_solve"),
                                      ("stacked", "algorithms.stacked", "stacked_solve"))}

    assert run(("speed", 0.5), ("speed", 1.0), ("speed", 2.0)) == {"direct": 0, "model": 0, "loop": 3,
                                                                 "stacked": 0}
    run(("loops", "open (Fig 9.1)"))                       # first time open: one scene build
    assert run(("speed", 0.7), ("loops", "closed (Fig 9.2)"), ("loops", "open (Fig 9.1)")) == {
        "direct": 0, "model": 0, "loop": 1, "stacked": 2}   # everything cached
    assert run(("mass", 2.0)) == {"direct": 0, "model": 1, "loop": 0, "stacked": 1}  # a new model


@pytest.mark.parametrize("overlay, key", [("velocity poles", "v"), ("acceleration poles", "a")])
def test_poles_drawn_together_share_one_label(overlay, key):
    # the default state puts several velocity poles within a few pixels of the ground pivot: each
    # pole is named exactly once on the picture, and no two labelled poles are closer than 20 px
    ex = TreeExplorer(display="agg", **{overlay: True})
    pic = ex.picture()
    k = px_per_unit(pic)
    marks, named = {}, []
    for i in range(1, 10):
        el = elements(pic)[f"{key}{i}".translate(str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉"))]
        mark = parts(el, "mark")
        texts = [t["text"].split(" (")[0] for t in parts(el, "text") if t["text"] and not t.get("hidden")]
        named += [n for t in texts for n in t.split(", ")]
        if mark and texts:
            marks[el["symbol"]] = np.array([mark[0]["x"], mark[0]["y"]]) * k
    assert sorted(named) == sorted(f"{key}{i}".translate(str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉"))
                                   for i in range(1, 10))
    close = [(a, b) for a in marks for b in marks if a < b and np.hypot(*(marks[a] - marks[b])) < 20.0]
    assert close == []
    if key == "v":                                     # the default's pile at the pivot is named together
        assert any(len(t.split(", ")) > 2 for _id, t in shown_labels(pic) if t.startswith("v"))
    assert overlapping_labels(pic) + undescribed(pic) == []
