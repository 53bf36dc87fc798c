"""ImpulseExplorer (thesis 5.4, 6.93, figure 3.3) driven through controls, drags and Play, against hand numbers.

References by hand: the door is a uniform rod of length L = 0.9 and width w = 0.04 pivoted at its end
(``J_P = m (4L² + w²)/12``; reaction ``J (m d L / (2 J_P) − 1)``, zero at ``2L/3 + w²/(6L)``; free pole
``L/2 − ρ²/(d − L/2)``); the bat's mass, centre and moment are integrated here by the shoelace formulas
for the impulse-momentum balance; the motion after the blow is a rotation by ``ω t`` about the pole.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from _picture_checks import elements, problems
from planargeo.scenes.impulse import BODIES
from planargeo.widgets import ImpulseExplorer

L, W = 0.9, 0.04


def door(m, d, J=1.0):
    Jc = m * (L * L + W * W) / 12
    JP = Jc + m * (L / 2) ** 2
    return dict(omega=J * d / JP, reaction=J * (m * d * L / (2 * JP) - 1), cop=2 * L / 3 + W * W / (6 * L),
                held=JP / d ** 2, free=1.0 / (1.0 / m + (d - L / 2) ** 2 / Jc),
                free_pole=None if d == L / 2 else L / 2 - (Jc / m) / (d - L / 2))


def legible(ex):
    """Every element of the picture has its symbol and description; no two labels overlap."""
    found = problems(ex.picture())
    assert found == [], found


def body_xy(ex):
    """The drawn body's outline (picture data: rounded to 1e-5 of this view)."""
    (part,) = [p for p in elements(ex.picture())["body"]["parts"] if p["p"] == "path"]
    return np.asarray(part["xy"], float)


@pytest.fixture
def ex():
    return ImpulseExplorer(display="agg", body="door", m=3.0)


def test_dragging_the_blow_along_the_door_follows_the_rod_closed_forms(ex):
    for d in (0.15, 0.3, 0.45, 0.7, 0.85):
        ex.drag("blow point", (ex.values["strike x"], 0.0), (d, 0.0), steps=3)
        assert ex.values["strike x"] == pytest.approx(d, abs=1e-15)
        ref = door(3.0, d)
        r = ex.readout_values
        assert r["ω after the blow"] == pytest.approx(ref["omega"], rel=1e-12)
        assert r["reaction impulse ĵᵣ, across"] == pytest.approx(ref["reaction"], rel=1e-10)
        assert r["apparent mass along ĵ"] == pytest.approx(ref["held"], rel=1e-12)
        assert r["apparent mass, free"] == pytest.approx(ref["free"], rel=1e-12)
        assert r["velocity pole"] == "(0, 0) m"
        assert ex.state.quantities["pole"] == pytest.approx((0.0, 0.0), abs=1e-15)
        if ref["free_pole"] is None:                       # struck through c: a free body translates
            assert r["pole if free (I⁻¹ĵ)"].startswith("at infinity (direction")
        else:
            assert ex.state.quantities["pole_if_free"] == pytest.approx((ref["free_pole"], 0.0), rel=1e-12,
                                                                         abs=1e-15)
            assert r["pole if free (I⁻¹ĵ)"] == f"({ref['free_pole']:.4g}, 0) m"
        assert ex.units["reaction impulse ĵᵣ, across"] == "N·s" and ex.units["apparent mass along ĵ"] == "kg"
        legible(ex)


def test_at_the_centre_of_percussion_the_hinge_feels_nothing(ex):
    cop = door(3.0, 0.5)["cop"]
    assert ex.readout_values["centre of percussion (5.67)"] == pytest.approx((cop, 0.0), rel=1e-12, abs=1e-15)
    ex.drag("blow point", (0.55, 0.0), (cop, 0.0), steps=4)
    assert ex.readout_strings["reaction impulse ĵᵣ, across"] == "0 N·s"      # round-off shown as 0
    assert ex.readout_strings["|ĵᵣ|"] == "0 N·s"
    assert ex.state.quantities["pole_if_free"] == pytest.approx((0.0, 0.0), abs=1e-12)
    assert ex.readout_values["pole if free (I⁻¹ĵ)"] == "(0, 0) m"
    els = elements(ex.picture())
    assert "reaction" not in els and "free pole" not in els           # no sting; the free pole is the hinge
    assert [p["text"] for p in els["P"]["parts"] if p["p"] == "text"] == ["P (hinge) ≈ pole if free"]
    legible(ex)
    ex.set(support="free")                                        # free, it turns about the hinge point
    assert ex.state.quantities["pole"] == pytest.approx((0.0, 0.0), abs=1e-12)
    legible(ex)


def test_blow_tip_drag_sets_angle_and_impulse_and_the_along_part_goes_into_the_hinge(ex):
    tip = ex.handles()[1].where()
    ex.drag("blow tip", tip, (0.55 + 0.1, 0.1 * math.sqrt(3.0)), steps=5)   # 60°, |tip − point| = 0.2
    assert ex.values["strike angle"] == pytest.approx(60.0, rel=1e-12)
    J = 2 * 0.2 / 0.25
    assert ex.values["J"] == pytest.approx(J, rel=1e-12)
    ref = door(3.0, 0.55, J=J * math.sin(math.radians(60.0)))
    assert ex.readout_values["reaction impulse ĵᵣ, across"] == pytest.approx(ref["reaction"], rel=1e-10)
    assert ex.readout_values["reaction impulse ĵᵣ, along"] == pytest.approx(-J * 0.5, rel=1e-12)
    legible(ex)


def test_a_drag_to_no_blow_keeps_the_last_good_state(ex):
    shown, readout = dict(ex.values), dict(ex.readout_values)
    tip = ex.handles()[1].where()
    ex.drag("blow tip", tip, (0.55, 0.0), steps=1)                 # the tip onto the point: no impulse
    assert "impulse J would be 0" in ex.message
    assert ex.values == shown and ex.readout_values == readout
    ex.set(J=0.0)
    assert "J must be non-zero" in ex.message and ex.values["J"] == shown["J"]
    ex.set(J=2.0)
    assert ex.message == ""


def shoelace(poly):
    p = np.asarray(poly, float)
    x, y = p[:, 0], p[:, 1]
    x1, y1 = np.roll(x, -1), np.roll(y, -1)
    cr = x * y1 - x1 * y
    A = cr.sum() / 2
    c = np.array([((x + x1) * cr).sum(), ((y + y1) * cr).sum()]) / (6 * A)
    Jo = (((x * x + x * x1 + x1 * x1) + (y * y + y * y1 + y1 * y1)) * cr).sum() / 12
    return A, c, Jo - A * c @ c


@pytest.mark.parametrize("support", ["held", "free"])
def test_bat_momentum_balance_from_the_readout(support):
    ex = ImpulseExplorer(display="agg", support=support)
    ex.drag("blow point", (0.55, 0.0), (0.72, 0.02), steps=3)
    ex.set(**{"strike angle": 75.0, "J": 2.0})
    m = ex.values["m"]
    A, c, Jc = shoelace(BODIES["bat"])
    Jc *= m / A
    r = ex.readout_values
    e = 2.0 * np.array([math.cos(math.radians(75.0)), math.sin(math.radians(75.0))])
    jr = np.array([r["reaction impulse ĵᵣ, along"], r["reaction impulse ĵᵣ, across"]])   # c lies on +x
    np.testing.assert_allclose(m * np.array(r["velocity of c"]), e + jr, atol=1e-12)
    moment = (0.72 - c[0]) * e[1] - (0.02 - c[1]) * e[0] + (-c[0]) * jr[1] - (-c[1]) * jr[0]
    assert Jc * r["ω after the blow"] == pytest.approx(moment, abs=1e-12)
    assert r["kinetic energy"] == pytest.approx(0.5 * m * np.array(r["velocity of c"]) @ np.array(r["velocity of c"])
                                                + 0.5 * Jc * r["ω after the blow"] ** 2, rel=1e-12)
    if support == "free":
        assert r["|ĵᵣ|"] == 0.0 and r["velocity pole"] == r["pole if free (I⁻¹ĵ)"]
    legible(ex)


def test_play_turns_the_body_about_its_pole(ex):
    ex.drag("blow point", (0.55, 0.0), (0.3, 0.0), steps=2)
    omega = door(3.0, 0.3)["omega"]
    outline = np.array(BODIES["door"])
    ex.advance(4)
    t = ex.values["t"]
    assert t == pytest.approx(4 / ex.play_fps, rel=1e-12)
    c, s = math.cos(omega * t), math.sin(omega * t)
    np.testing.assert_allclose(body_xy(ex), outline @ np.array([[c, s], [-s, c]]), atol=1e-5)
    legible(ex)
    ex.set(support="free")
    free_door(ex, t)
    ex.advance(100)                                          # Play keeps moving it (exact at any t)
    t = ex.values["t"]
    assert t == pytest.approx(104 / ex.play_fps, rel=1e-12)
    free_door(ex, t)
    legible(ex)


def free_door(ex, t, m=3.0, d=0.3, J=1.0):
    """A free door struck across at ``d`` keeps its momentum: ``c`` moves straight on at ``J / m`` across
    and the door turns about ``c`` at ``ω = J (d − L/2) / J_c`` (no force after the blow: ``c`` cannot
    circle a fixed pole)."""
    Jc = m * (L * L + W * W) / 12
    w, vc = J * (d - L / 2) / Jc, np.array([0.0, J / m])
    assert ex.readout_values["ω after the blow"] == pytest.approx(w, rel=1e-12)
    c0 = np.array([L / 2, 0.0])
    ct, s = math.cos(w * t), math.sin(w * t)
    moved = (np.array(BODIES["door"]) - c0) @ np.array([[ct, s], [-s, ct]]) + c0 + vc * t
    np.testing.assert_allclose(body_xy(ex), moved, atol=1e-5 * (1 + np.abs(moved).max()))
    mark = [p for p in elements(ex.picture())["c"]["parts"] if p["p"] == "mark"][0]
    np.testing.assert_allclose([mark["x"], mark["y"]], c0 + vc * t, atol=1e-5 * (1 + t))
    R = np.array([[ct, s], [-s, ct]])
    grip = (np.zeros(2) - c0) @ R + c0 + vc * t                      # the hinge end of the door
    cop = (np.array(ex.readout_values["centre of percussion (5.67)"]) - c0) @ R + c0 + vc * t
    on_body_axis(ex, grip, c0 + vc * t, cop, 1e-5 * (1 + t))
    in_view(ex)


def on_body_axis(ex, grip, c, cop, tol):
    """The grip P and the centre of percussion drawn at their moved places, the axis of percussion of P
    through the centre of percussion, across the line P c (5.67)."""
    els = elements(ex.picture())
    (P,) = [p for p in els["P"]["parts"] if p["p"] == "mark"]
    np.testing.assert_allclose([P["x"], P["y"]], grip, atol=tol)
    (mark,) = [p for p in els["centre of percussion"]["parts"] if p["p"] == "mark"]
    np.testing.assert_allclose([mark["x"], mark["y"]], cop, atol=tol)
    (seg,) = [np.asarray(p["xy"], float) for p in els["axis"]["parts"] if p["p"] == "path"]
    u = (seg[1] - seg[0]) / np.hypot(*(seg[1] - seg[0]))
    n = (c - grip) / np.hypot(*(c - grip))
    assert abs(u @ n) < 1e-4 and abs((cop - seg[0]) @ np.array([-u[1], u[0]])) < 1e-4


def in_view(ex):
    """The body's whole outline, c and the circle of gyration are inside the picture's view."""
    x0, x1, y0, y1 = ex.picture()["box"]
    els = elements(ex.picture())
    pts = [body_xy(ex)] + [[[p["x"], p["y"]]] for p in els["c"]["parts"] if p["p"] == "mark"]
    (ell,) = [p for p in els["I"]["parts"] if p["p"] == "ellipse"]
    r = max(abs(v) for v in ell["m"])
    pts.append([[ell["x"] - r, ell["y"] - r], [ell["x"] + r, ell["y"] + r]])
    pts = np.vstack(pts)
    assert (pts[:, 0] >= x0).all() and (pts[:, 0] <= x1).all() and (pts[:, 1] >= y0).all() \
        and (pts[:, 1] <= y1).all(), ((x0, x1, y0, y1), pts.min(axis=0), pts.max(axis=0))


@pytest.mark.parametrize("body", ["bat", "door"])
def test_play_carries_c_its_circle_and_the_centre_of_percussion_with_the_body_and_keeps_it_in_view(body):
    """Issue: during Play the bat swung about the grip out of the fixed view, while c and the I(ρ) circle
    stayed at their t = 0 places.  Held, every body-fixed point turns by ω t about the grip: c, the
    circle's centre and the centre of percussion keep their distances from the grip and turn with the
    outline; over a whole turn everything stays in the one view Play uses."""
    ex = ImpulseExplorer(display="agg", body=body)
    A, c_ref, _Jc = shoelace(BODIES[body])
    outline = np.array(BODIES[body])
    w = ex.readout_values["ω after the blow"]
    cop0 = np.array(ex.readout_values["centre of percussion (5.67)"])
    boxes = set()
    steps = int(math.ceil(2 * math.pi / abs(w) * ex.play_fps / 12))          # 12 frames per turn
    for _ in range(13):
        ex.advance(steps)
        t = ex.values["t"]
        ct, s = math.cos(w * t), math.sin(w * t)
        R = np.array([[ct, s], [-s, ct]])
        np.testing.assert_allclose(body_xy(ex), outline @ R, atol=2e-5)
        els = elements(ex.picture())
        (mark,) = [p for p in els["c"]["parts"] if p["p"] == "mark"]
        np.testing.assert_allclose([mark["x"], mark["y"]], c_ref @ R, atol=2e-5)     # body-fixed about the grip
        (ell,) = [p for p in els["I"]["parts"] if p["p"] == "ellipse"]
        np.testing.assert_allclose([ell["x"], ell["y"]], c_ref @ R, atol=2e-5)
        (cop,) = [p for p in els["centre of percussion"]["parts"] if p["p"] == "mark"]
        np.testing.assert_allclose([cop["x"], cop["y"]], cop0 @ R, atol=2e-5)
        on_body_axis(ex, np.zeros(2), c_ref @ R, cop0 @ R, 2e-5)
        in_view(ex)
        boxes.add(tuple(ex.picture()["box"]))
        legible(ex)
    assert len(boxes) == 1                                   # one view for the whole swing


def test_the_animation_export_keeps_the_whole_bat_in_every_frame(tmp_path):
    """The GIF of a whole turn (12 frames, 0.25 s apart, ω = 2.23 rad/s): the bat's fill covers the same
    area in every frame (a bat partly out of the view covers less)."""
    from PIL import Image

    from planargeo.draw.style import COLORS

    ex = ImpulseExplorer(display="agg")
    w = ex.readout_values["ω after the blow"]
    assert 11 * 0.25 * abs(w) > 2 * math.pi * 0.95                            # the frames span a whole turn
    gif = ex.export_animation(tmp_path / "a.gif", frames=12, fps=4)
    fill = np.array([int(COLORS["body"][k:k + 2], 16) for k in (1, 3, 5)])
    im = Image.open(gif)
    areas = []
    for k in range(im.n_frames):
        im.seek(k)
        rgb = np.asarray(im.convert("RGB"), dtype=int)
        shade = 255 - 0.6 * (255 - fill)                                       # the fill at alpha 0.6 on white
        areas.append(int(np.sum(np.abs(rgb - shade).sum(axis=-1) < 40)))
    assert len(areas) == 12 and min(areas) > 0.85 * max(areas), areas
