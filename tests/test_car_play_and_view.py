"""Car explorer (issues 22 and 23): Play runs a minute from the default, the friction limit is a stated
event at its exact time (no silent cap), the car fills a third of its view, tiny drives are computed, one
state per set of controls, every symbol explained."""
import math

import pytest

from planargeo.widgets.car import CarExplorer, view_box

DRIVE, SPEED, RADIUS, HEADING, FRICTION = ("drive force (N)", "speed (m/s)", "turn radius (m)", "heading (deg)",
                                           "tyre friction μ")
L, EPS, M, RHO = 2.6, 0.45, 1200.0, 1.2


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
    assert ex.message == "" and ex.banner.get_text() == "the car slides out: its tyres reach μ·g"
    assert ex.readout_values["tyres"].startswith("slide")
    assert ex.readout_values["acceleration of G"] == pytest.approx(0.9 * 9.81, rel=1e-9)
    n = ex.n_updates
    ex.advance(3)
    assert ex.n_updates == n                                                # Play has ended
    ex.set(**{FRICTION: 1.2})                                               # better tyres: it holds again
    assert ex.banner.get_text() == "" and ex.readout_values["tyres"].startswith("hold")


@pytest.mark.parametrize("heading", [0.0, 37.0, 90.0, 200.0])
def test_the_car_fills_a_third_of_its_view_and_the_view_holds_the_car_and_the_icr(heading):
    ex = CarExplorer(display="agg", **{HEADING: heading})
    x0, x1 = ex.ax.get_xlim()
    y0, y1 = ex.ax.get_ylim()
    body = ex.body.get_xy()
    if heading == 0.0:
        length = body[:, 1].max() - body[:, 1].min()
        assert length >= (y1 - y0) / 3
    icr = ex.handles()[2].where()
    for x, y in list(body) + [icr]:
        assert x0 <= x <= x1 and y0 <= y <= y1
    assert (x0, x1, y0, y1) == pytest.approx(view_box(8.0, L, math.radians(heading)))


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
    assert fresh.ax.get_xlim() == ex.ax.get_xlim() and fresh.ax.get_ylim() == ex.ax.get_ylim()


def test_every_readout_row_and_label_is_explained():
    ex = CarExplorer(display="agg", **{DRIVE: 2000.0})
    meaning = ex.explain()
    for k in ex.readout_values:
        assert k in meaning, k
        assert "(" not in k                                  # units are the readout's, not in the names
    for lab in ("G", "a", "v = sω (ICR)", "R₁μ₁", "R₂μ₂", "f_A", "p", "T", "I"):
        assert lab in meaning
