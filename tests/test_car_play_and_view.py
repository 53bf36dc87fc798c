"""Car explorer (issues 22 and 23): Play runs a minute from the default, the friction limit is a stated
event at its exact time (no silent cap), the car fills a third of its view, tiny drives are computed, one
state per set of controls, every symbol explained."""
import math

import numpy as np
import pytest

from picture_checks import elements, parts
from planargeo.widgets.car import CarExplorer, view_box

DRIVE, SPEED, RADIUS, HEADING, FRICTION = ("drive force (N)", "speed (m/s)", "turn radius (m)", "heading (deg)",
                                           "tyre friction μ")
L, EPS, M, RHO = 2.6, 0.45, 1200.0, 1.2


def banner(ex) -> str:
    """The banner's text on the picture ("" when there is none)."""
    el = elements(ex.picture()).get("banner")
    return "" if el is None else el["parts"][0]["text"]


def test_play_runs_a_minute_from_the_default():
    ex = CarExplorer(display="agg")
    ex.advance(60, seconds=60.0)
    assert ex.message == "" and ex.values[SPEED] == pytest.approx(4.0)
    # constant speed round the circle: 60 s at ω = 0.5 rad/s
    assert ex.values[HEADING] == pytest.approx(math.degrees(0.5 * 60.0) % 360.0, abs=1e-6)
    assert ex.readout_values["tyres"].startswith("hold")


def test_a_drive_ends_in_the_stated_slide_at_the_friction_limit():
    """The drive speeds the car up until the centre of gravity needs μ·g: there the car slides out, stated."""
    ex = CarExplorer(display="agg", **{DRIVE: 2000.0})
    d = 8.0
    r_g = math.hypot(d, (1 - EPS) * L)
    wd = math.hypot(d, L) * 2000.0 / (M * (RHO ** 2 + r_g ** 2))          # 6.131 by hand
    w_end = ((0.9 * 9.81 / r_g) ** 2 - wd ** 2) ** 0.25                     # r_G √(ω⁴ + ω̇²) = μ g
    ex.advance(100, seconds=60.0)
    assert ex.values[SPEED] == pytest.approx(w_end * d, rel=1e-9)           # stopped exactly there
    assert ex.values[SPEED] < ex.controls[SPEED].max                        # not the slider's cap
    assert ex.message == "" and banner(ex) == "the car slides out: its tyres reach μ·g"
    assert ex.readout_values["tyres"].startswith("slide")
    assert ex.readout_values["acceleration of G"] == pytest.approx(0.9 * 9.81, rel=1e-9)
    n = ex.n_updates
    ex.advance(3)
    assert ex.n_updates == n                                                # Play has ended
    ex.set(**{FRICTION: 1.2})                                               # better tyres: it holds again
    assert banner(ex) == "" and ex.readout_values["tyres"].startswith("hold")


@pytest.mark.parametrize("heading", [0.0, 37.0, 90.0, 200.0])
@pytest.mark.parametrize("radius", [8.0, 40.0])
def test_the_car_fills_a_third_of_its_view_and_the_view_holds_the_car_and_a_near_icr(heading, radius):
    ex = CarExplorer(display="agg", **{HEADING: heading, RADIUS: radius})
    x0, x1, y0, y1 = ex.view_of(ex.state)
    body = np.array(parts(elements(ex.picture())["body"], "path")[0]["xy"])
    th = math.radians(heading)
    # the body by hand: 1.6 m wide, 0.7 m beyond each axle, turned by the heading about the ICR (-d, 0)
    corners = np.array([[-0.8, -0.7], [0.8, -0.7], [0.8, L + 0.7], [-0.8, L + 0.7]])
    rot = np.array([[math.cos(th), -math.sin(th)], [math.sin(th), math.cos(th)]])
    expected = (corners + [radius, 0.0]) @ rot.T + [-radius, 0.0]
    assert body == pytest.approx(expected, abs=1e-4)
    if heading == 0.0:
        length = body[:, 1].max() - body[:, 1].min()
        assert length >= (y1 - y0) / 3
    icr = ex.handles()[2].where()
    for x, y in list(body) + ([icr] if radius <= 10.0 else []):
        assert x0 <= x <= x1 and y0 <= y <= y1
    assert (x0, x1, y0, y1) == pytest.approx(view_box(radius, L, th))
    if radius > 10.0:                      # a far ICR: out of view, an arrow at the edge points to it
        icr_el = elements(ex.picture())["ICR"]
        assert parts(icr_el, "arrow") and not parts(icr_el, "mark")
        assert not (x0 <= icr[0] <= x1 and y0 <= icr[1] <= y1)


def test_a_tiny_drive_is_computed():
    ex = CarExplorer(display="agg")
    ex.set(**{DRIVE: 1e-300})
    assert ex.message == "" and ex.values[DRIVE] == 1e-300
    assert abs(ex.readout_values["yaw acceleration ω̇"]) < 1e-15
    assert ex.readout_strings["yaw acceleration ω̇"] == "0 rad/s²"


def test_one_state_per_set_of_controls_after_play_and_drags():
    ex = CarExplorer(display="agg", **{DRIVE: 1500.0})
    ex.advance(7)
    ex.drag("centre of gravity", ex.handles()[0].where(), (0.0, 1.0), steps=3)
    ex.advance(3)
    fresh = CarExplorer(display="agg", **ex.values)
    assert fresh.readout_values == ex.readout_values and fresh.message == ex.message
    assert fresh.view_of(fresh.state) == ex.view_of(ex.state) and fresh.picture() == ex.picture()


def test_every_readout_row_and_label_is_explained():
    ex = CarExplorer(display="agg", **{DRIVE: 2000.0})
    meaning = ex.explain()
    for k in ex.readout_values:
        assert k in meaning, k
        assert "(" not in k                                  # units are the readout's, not in the names
    for lab in ("G", "a", "v = sω (ICR)", "R₁μ₁", "R₂μ₂", "f (drive)", "p", "T", "I"):
        assert lab in meaning


def test_a_fresh_car_after_a_long_drag_history_shows_the_same_state():
    """``make fuzz`` once found a fresh CarExplorer slow after a long history of drags (some far beyond the
    view, as the fuzzer makes them); the fresh one must show the same state, picture and all."""
    import random

    rng = random.Random(3)
    ex = CarExplorer(display="agg", **{DRIVE: 1000.0})
    for _ in range(40):
        h = rng.choice([h for h in ex.all_handles() if h.where() is not None])
        start = h.where()
        x0, x1, y0, y1 = ex.view_of(ex.state)
        far = rng.choice([0.02, 0.2, 0.6, 3.0, 1e3, 1e6]) * max(x1 - x0, y1 - y0)
        ang = rng.uniform(0.0, 2 * math.pi)
        ex.drag(h.name, start, (start[0] + far * math.cos(ang), start[1] + far * math.sin(ang)), rng.choice([1, 2, 5]))
        if rng.random() < 0.2:
            ex.advance(rng.choice([1, 3]))
    fresh = CarExplorer(display="agg", **ex.values)
    assert fresh.message == "" and fresh.readout_values == ex.readout_values
    # the last drag was refused: its message is on the picture and the labels keep clear of it; the
    # shown state is drawn again without it (a control moved and back) before the pictures are compared
    if ex.message:
        mu = ex.values[FRICTION]
        ex.set(**{FRICTION: 1.1 if mu == 1.2 else 1.2})
        ex.set(**{FRICTION: mu})
    assert ex.message == "" and ex.picture() == fresh.picture()


@pytest.mark.parametrize("heading", [0.0, 120.0])
def test_keyboard_nudges_hold_the_view_and_their_release_fits_it_again(heading):
    """Arrow keys nudge a handle by 2 px, each a ``drag`` message; letting go sends ``release``
    (canvas.js; the page's side: tests/browser/test_keyboard_release.py).  The nudges keep the view they
    began in; the release shows what a fresh explorer of the same values shows."""
    ex = CarExplorer(display="page", **{HEADING: heading})
    c = ex.canvas
    before = c.picture["box"]
    x, y = ex.handle_position("ICR")
    step = 2.0 / c.picture["size"][0] * (before[1] - before[0])        # about 2 px of the view
    ux, uy = math.cos(math.radians(heading)), math.sin(math.radians(heading))   # along the rear axle line
    for k in range(1, 6):                                               # five presses: the ICR nearer
        assert c.handle_message({"type": "drag", "id": "ICR", "x": x + k * step * ux, "y": y + k * step * uy,
                                 "seq": k}) == (True, "")
    assert ex.values[RADIUS] == pytest.approx(8.0 - 5 * step, abs=1e-9)
    assert c.picture["box"] == before                                    # the view held while nudged
    assert c.handle_message({"type": "release", "id": "ICR", "seq": 9}) == (True, "")
    fresh = CarExplorer(display="page", **ex.values)
    assert c.picture == fresh.canvas.picture
    assert c.picture["box"] != before                                    # fitted to the nearer ICR
