"""CarExplorer as an instrument (issue 13): labels, drags, Play round the turn, energy.

Independent references: the turn radius from the steering angle by the
Ackermann-free geometry of Fig 6.6 (``d = L / tan δ``, the ICR where the front
axle meets the rear axle line), ``ε`` from where the centre of gravity is
dragged, the yaw motion under a constant moment by hand (``ω̇ = M / J`` with
``J = m (ρ² + |c|²)`` about the ICR and ``M = √(d² + L²) F_A``, 6.120), the tyre
forces of each Play frame from an independent Newton-Euler solve
(tests/test_widgets_car.py), the kinetic energy against the drive's work.
"""
import math

import numpy as np
import pytest

from picture_checks import elements, overlapping_labels, parts, shown_labels, undescribed
from planargeo.widgets.car import CarExplorer
from test_widgets_car import newton_euler

L = 2.6
EPS, RADIUS, DRIVE, SPEED, HEADING = ("centre of mass ε (× L)", "turn radius (m)", "drive force (N)",
                                      "speed (m/s)", "heading (deg)")


@pytest.fixture
def ex():
    return CarExplorer(display="agg", **{DRIVE: 2000.0})          # the drive of Fig 6.6


def legibility_problems(ex) -> list:
    """Overlapping labels and elements without a symbol or a description with its value."""
    pic = ex.picture()
    return overlapping_labels(pic) + undescribed(pic)


def test_every_element_labelled_and_legible(ex):
    texts = [t for _id, t in shown_labels(ex.picture())]
    for sym in ("G", "a", "v = sω (ICR)", "R₁μ₁", "R₂μ₂", "f (drive)", "p", "T", "I"):
        assert sym in texts, sym
    assert legibility_problems(ex) == []
    assert ex.units["rear tyre force μ₁"] == "N" and ex.readout_strings["rear tyre force μ₁"].endswith(" N")


def test_drag_centre_of_gravity_sets_eps(ex):
    start = ex.handles()[0].where()
    assert start == pytest.approx((0.0, (1 - 0.45) * L))          # the rear tyre is drawn at the origin
    ex.drag("centre of gravity", start, (0.3, 0.8), steps=4)        # sideways is ignored (centre line)
    assert ex.message == "" and ex.values[EPS] == pytest.approx(1 - 0.8 / L)
    assert ex.handles()[0].where() == pytest.approx((0.0, 0.8))
    ex.drag("centre of gravity", (0.0, 0.8), (0.0, 3.5), steps=1)   # ahead of the front axle
    assert "between the axles" in ex.message and ex.values[EPS] == pytest.approx(1 - 0.8 / L)
    assert legibility_problems(ex) == []


@pytest.mark.parametrize("delta_deg", [10.0, 30.0, 50.0])
def test_steering_drag_moves_the_icr_to_l_over_tan_delta(ex, delta_deg):
    delta = math.radians(delta_deg)
    front = np.array([0.0, L])
    axle = -np.array([math.cos(delta), math.sin(delta)])            # the front axle line, wheel turned left by δ
    ex.drag("steering", ex.handles()[1].where(), front + 1.3 * axle, steps=5)
    d = L / math.tan(delta)
    r_g = math.hypot(d, (1 - 0.45) * L)
    acc = r_g * math.hypot((4.0 / d) ** 2, ex.readout_values["yaw acceleration ω̇"])
    # a tight turn at 4 m/s asks more of the tyres than μ·g = 0.9 × 9.81: the car slides out (stated)
    assert ex.message == ""
    assert ex.readout_values["tyres"].startswith("slide" if acc >= 0.9 * 9.81 else "hold")
    assert ex.values[RADIUS] == pytest.approx(d, rel=1e-9)
    assert ex.readout_values["steering angle"] == pytest.approx(delta_deg)
    assert ex.handles()[2].where() == pytest.approx((-d, 0.0))     # the ICR moved, the car did not
    assert legibility_problems(ex) == []


def test_steering_right_or_straight_is_refused(ex):
    shown = dict(ex.readout_values)
    ex.drag("steering", ex.handles()[1].where(), (0.5, L + 0.5), steps=1)
    assert "steering angle must turn the car left" in ex.message and ex.readout_values == shown
    assert legibility_problems(ex) == []


def test_icr_drag_sets_the_radius(ex):
    ex.drag("ICR", ex.handles()[2].where(), (-15.0, 0.4), steps=3)
    assert ex.message == "" and ex.values[RADIUS] == pytest.approx(15.0)
    ex.drag("ICR", (-15.0, 0.0), (1.0, 0.0), steps=1)
    assert "left of the rear tyre" in ex.message and ex.values[RADIUS] == pytest.approx(15.0)


def test_drive_drag_sets_the_force_along_the_front_wheel(ex):
    d = 8.0
    roll = np.array([-L, d]) / math.hypot(d, L)
    tip = np.array(ex.handles()[3].where())
    assert tip == pytest.approx(np.array([0.0, L]) + 2.0 * roll)    # 2000 N at 1 mm/N
    ex.drag("drive", tip, np.array([0.0, L]) - 1.5 * roll + 0.2 * np.array([roll[1], -roll[0]]), steps=4)
    assert ex.message == "" and ex.values[DRIVE] == pytest.approx(-1500.0)


def test_play_drives_round_the_turn_exactly_and_conserves_energy():
    ex = CarExplorer(display="agg", **{DRIVE: 1500.0, SPEED: 5.0})
    m, rho, d, eps = 1200.0, 1.2, 8.0, 0.45
    J = m * (rho ** 2 + d ** 2 + ((1 - eps) * L) ** 2)              # about the ICR (6.117)
    M = math.hypot(d, L) * 1500.0                                   # the drive's moment (6.120)
    wd = M / J
    w0 = 5.0 / d
    dt = ex.play_dt
    for k in range(1, 31):
        ex.advance(1)
        t = k * dt
        assert ex.message == ""
        assert ex.values[SPEED] == pytest.approx((w0 + wd * t) * d, rel=1e-9)
        assert ex.values[HEADING] == pytest.approx(math.degrees(w0 * t + 0.5 * wd * t * t) % 360, abs=1e-7)
        r = ex.readout_values
        assert r["yaw acceleration ω̇"] == pytest.approx(wd, rel=1e-9)
        assert r["kinetic energy K"] == pytest.approx(0.5 * J * (w0 + wd * t) ** 2, rel=1e-9)
        assert r["rate of change of K"] == pytest.approx(r["drive power"], rel=1e-9)   # the tyres do no work
        assert r["drive power"] == pytest.approx(M * (w0 + wd * t), rel=1e-9)
    # the tyre forces follow the speed (Newton-Euler at the frame's speed)
    _, mu1, mu2 = newton_euler(m, rho, d, eps, ex.values[SPEED], 1500.0)
    assert [r["rear tyre force μ₁"], r["front tyre force μ₂"]] == pytest.approx([mu1, mu2], rel=1e-9)
    # the drawing turned about the ICR (-d, 0) by the heading: the rear contact and its force line
    th = math.radians(ex.values[HEADING])
    rear = np.array([-d + d * math.cos(th), d * math.sin(th)])
    els = elements(ex.picture())
    assert np.array(parts(els["rear tyre"], "path")[0]["xy"]).mean(axis=0) == pytest.approx(rear, abs=1e-4)
    a, b = np.array(parts(els["R₁μ₁"], "path")[0]["xy"])        # the rear axle line, through the ICR
    for p in (rear, (-d, 0.0)):
        n = np.array([-(b - a)[1], (b - a)[0]]) / np.hypot(*(b - a))
        assert float((np.asarray(p) - a) @ n) == pytest.approx(0.0, abs=1e-3)
    assert legibility_problems(ex) == []


def test_play_stops_at_rest_when_braking_exactly_at_the_stop():
    ex = CarExplorer(display="agg", **{DRIVE: -6000.0, SPEED: 1.0})
    ex.advance(200)
    assert ex.values[SPEED] == 0.0 and ex.message == ""
    n = ex.n_updates
    ex.advance(5)                                  # stopped: Play ended
    assert ex.n_updates == n


def test_steering_lever_is_apart_from_the_drive_handle_and_steers_smoothly():
    """The steering handle is the end of a lever of about 100 px along the front axle line, ≥ 60 px from the
    drive handle; a 15 px drag across it turns the wheel by at most 9° (atan(15/100) = 8.5°, by hand),
    and the front axle line through it still meets the rear axle line at the ICR (d = L / tan δ)."""
    ex = CarExplorer(display="agg")                               # coasting: the drive handle on the tyre
    x0, x1, y0, y1 = ex.view_of(ex.state)
    px = ex.figure_px[0] / (x1 - x0)                              # pixels per metre of the view
    steer, drive = (np.array(ex.handles()[k].where()) for k in (1, 3))
    front = np.array([0.0, L])
    assert np.hypot(*(steer - front)) * px >= 99.0
    assert np.hypot(*(steer - drive)) * px >= 60.0
    d0 = ex.values[RADIUS]
    delta0 = math.atan2(L, d0)
    assert ex.readout_values["steering angle"] == pytest.approx(math.degrees(delta0))
    across = np.array([math.sin(delta0), -math.cos(delta0)])      # perpendicular to the lever
    ex.drag("steering", tuple(steer), tuple(steer + 15.0 / px * across), steps=3)
    assert ex.message == ""
    delta1 = math.radians(ex.readout_values["steering angle"])
    assert 0.0 < abs(delta1 - delta0) <= math.radians(9.0)
    assert ex.values[RADIUS] == pytest.approx(L / math.tan(delta1), rel=1e-9)
    end = np.array(ex.handles()[1].where())                       # on the line from the front to the ICR
    icr = np.array(ex.handles()[2].where())
    u, w = end - front, icr - front
    assert abs(u[0] * w[1] - u[1] * w[0]) <= 1e-9 * np.hypot(*u) * np.hypot(*w) and u @ w > 0


def _page_pointer(ex, qx, qy):
    """The data point under the pixel ``(qx, qy)`` (from the plot area's lower left) of the picture shown."""
    pic = ex.picture()
    x0, x1, y0, y1 = pic["box"]
    (w, h), (ml, mr, mt, mb) = pic["size"], pic["margin"]
    return x0 + qx * (x1 - x0) / (w - ml - mr), y0 + qy * (y1 - y0) / (h - mt - mb)


def _page_pixel(ex, x, y):
    pic = ex.picture()
    x0, x1, y0, y1 = pic["box"]
    (w, h), (ml, mr, mt, mb) = pic["size"], pic["margin"]
    return (x - x0) * (w - ml - mr) / (x1 - x0), (y - y0) * (h - mt - mb) / (y1 - y0)


@pytest.mark.parametrize("heading", [0.0, 90.0, 180.0])
def test_a_slow_steering_drag_in_the_page_turns_the_wheel_smoothly_and_keeps_the_view(heading):
    """The review dragged the lever's end down 2 px at a time in the page: the view zoomed in under the
    pointer and the wheel ran away (19°, 23°, 35°, 52°, then refused). Driven as the page drives it (the
    pointer's pixel read through the picture shown, no release), the view and the car must stay put and
    the wheel follow the pointer: δ = atan2(−r_y, −r_x) of the pointer r from the front tyre in the car's
    frame (the front tyre drawn at R (d, L) − (d, 0) when the drag begins, R the heading's turn); 2 px
    seen from r px away subtend at most asin(2/r)."""
    ex = CarExplorer(display="page", **{HEADING: heading})
    box = ex.picture()["box"]
    d0, th = ex.values[RADIUS], math.radians(heading)
    R = np.array([[math.cos(th), -math.sin(th)], [math.sin(th), math.cos(th)]])
    front = R @ [d0, L] - [d0, 0.0]
    qx, qy = _page_pixel(ex, *ex.handle_position("steering"))
    angles = [ex.readout_values["steering angle"]]
    bound = []
    for k in range(1, 13):
        x, y = _page_pointer(ex, qx, qy - 2.0 * k)
        ok, why = ex.canvas.handle_message({"type": "drag", "id": "steering", "x": x, "y": y, "seq": k})
        assert ok and ex.message == "", why
        assert ex.picture()["box"] == box
        r = R.T @ (np.array([x, y]) - front)
        angles.append(ex.readout_values["steering angle"])
        assert angles[-1] == pytest.approx(math.degrees(math.atan2(-r[1], -r[0])), abs=1e-9)
        assert ex.values[RADIUS] == pytest.approx(L / math.tan(math.radians(angles[-1])), rel=1e-9)
        bound.append(math.degrees(math.asin(2.0 / min(np.hypot(*np.subtract(_page_pixel(ex, *p), _page_pixel(
            ex, *front))) for p in (_page_pointer(ex, qx, qy - 2.0 * (k - 1)), (x, y))))))
    steps = np.diff(angles)
    assert np.all(steps > 0.0) or np.all(steps < 0.0), steps               # monotonic
    assert np.all(np.abs(steps) <= np.array(bound) + 1e-9), (steps, bound)
    if heading != 0.0:
        return
    ex = CarExplorer(display="page")
    # a diagonal drag of 15 × 10 px after Reset (refused at 153° in the review)
    qx, qy = _page_pixel(ex, *ex.handle_position("steering"))
    before = ex.readout_values["steering angle"]
    for k in range(1, 6):
        x, y = _page_pointer(ex, qx + 3.0 * k, qy - 2.0 * k)
        ok, why = ex.canvas.handle_message({"type": "drag", "id": "steering", "x": x, "y": y, "seq": 40 + k})
        assert ok and ex.message == "", why
        after = ex.readout_values["steering angle"]
        assert after == pytest.approx(math.degrees(math.atan2(-(y - L), -x)), abs=1e-9)
        assert 0.0 < after - before < 3.0                   # 3.6 px, ≥ 75 px from the tyre: < 2.8°
        before = after
    # a slider's change ends the held view: the view fits the state again, as a fresh explorer's
    ex.set(**{SPEED: 5.0})
    assert ex.picture()["box"] == CarExplorer(display="agg", **ex.values).picture()["box"]
    # and the radius slider's step turns the wheel by under 1° even at its smallest radius
    w = ex.controls[RADIUS]
    assert math.degrees(math.atan(L / w.min) - math.atan(L / (w.min + w.step))) < 1.0


def test_letting_go_of_a_page_drag_fits_the_view_to_the_state_again():
    # the page says when the mouse lets go ("release", after the drag's last request): the held
    # view ends there, as at the end of a drag from Python, not at the next slider change
    ex = CarExplorer(display="page", **{HEADING: 90.0})
    qx, qy = _page_pixel(ex, *ex.handle_position("steering"))
    for k in range(1, 6):
        x, y = _page_pointer(ex, qx, qy - 2.0 * k)
        ok, why = ex.canvas.handle_message({"type": "drag", "id": "steering", "x": x, "y": y, "seq": k})
        assert ok, why
    held = ex.picture()["box"]
    fresh = CarExplorer(display="agg", **ex.values).picture()["box"]
    assert held != fresh                                   # the drag moved the state under a held view
    ok, why = ex.canvas.handle_message({"type": "release", "id": "steering", "seq": 9})
    assert ok, why
    assert ex.picture()["box"] == fresh and ex.message == ""
    ok, why = ex.canvas.handle_message({"type": "release", "id": "no such handle", "seq": 10})
    assert not ok and "no handle" in why
