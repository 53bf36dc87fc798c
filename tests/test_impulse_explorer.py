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
    ex.set(support="free")                                    # free: about the percussion pole of the blow
    p = np.array([door(3.0, 0.3)["free_pole"], 0.0])
    w = ex.readout_values["ω after the blow"]
    c, s = math.cos(w * t), math.sin(w * t)
    np.testing.assert_allclose(body_xy(ex), (outline - p) @ np.array([[c, s], [-s, c]]) + p,
                               atol=1e-5)
    ex.advance(100)                                          # Play keeps turning it (exact at any t)
    t = ex.values["t"]
    assert t == pytest.approx(104 / ex.play_fps, rel=1e-12)
    c, s = math.cos(w * t), math.sin(w * t)
    np.testing.assert_allclose(body_xy(ex), (outline - p) @ np.array([[c, s], [-s, c]]) + p,
                               atol=1e-5)
    legible(ex)


def test_play_runs_a_minute_from_the_default_exactly_for_any_step():
    from planargeo.widgets.impulse import ImpulseExplorer

    ex = ImpulseExplorer(display="agg")
    ex.advance(60, seconds=60.0)
    assert ex.message == "" and ex.values["t"] == pytest.approx(60.0, rel=1e-12)
    # sub-steps of any size add up exactly: one step of 0.0137 s from t = 1.0
    assert ex.play_step(dict(ex.values, t=1.0), 0.0137) == {"t": 1.0137}
    assert ex.play_step(dict(ex.values, t=60.0), 0.01) is None               # the end of the time slider


def test_every_readout_row_and_label_is_explained_and_points_read_as_points():
    from planargeo.widgets.impulse import ImpulseExplorer

    ex = ImpulseExplorer(display="agg", support="free", **{"strike angle": 0.0})   # a blow along the bat
    meaning = ex.explain()
    for k in ex.readout_values:
        assert k in meaning and "_" not in k, k
    # a blow through the centre of mass along the bat: a translation, its pole at infinity
    assert ex.readout_values["velocity pole"].startswith("at infinity (direction")


def test_every_body_and_support_is_legible_and_exports(tmp_path):
    ex = ImpulseExplorer(display="agg")
    for body in BODIES:
        for support in ("held", "free"):
            ex.set(body=body, support=support)
            assert ex.message == ""
            legible(ex)
    assert ex.export_svg(tmp_path / "i.svg").stat().st_size > 1000
    assert ex.export_png(tmp_path / "i.png").read_bytes()[:4] == b"\x89PNG"
    gif = ex.export_animation(tmp_path / "i.gif", frames=4, fps=10)
    assert gif.read_bytes()[:6] in (b"GIF89a", b"GIF87a")
    assert [h.name for h in ex.handles()] == ["blow point", "blow tip"]
