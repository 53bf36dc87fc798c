"""CarExplorer: tyre forces against an independent Newton-Euler solve about the ICR."""
import math

import numpy as np
import pytest

from picture_checks import elements, on_line, parts
from planargeo.widgets.car import CarExplorer

L = 2.6


def newton_euler(m, rho, d, eps, V, FA):
    """Unknowns (ω̇, μ_rear, μ_front): m a_cg = ΣF, m ρ² ω̇ = Σ moments about the CG."""
    w = V / d
    c = np.array([d, (1 - eps) * L])
    rear, front = np.array([d, 0.0]), np.array([d, L])
    e1 = np.array([1.0, 0.0])
    e2 = np.array([d, L]) / math.hypot(d, L)
    roll = np.array([-L, d]) / math.hypot(d, L)
    cross = lambda r, f: r[0] * f[1] - r[1] * f[0]
    # a_cg = ω̇ k×c − ω² c
    kc = np.array([-c[1], c[0]])
    A = np.array([[m * kc[0], -e1[0], -e2[0]],
                  [m * kc[1], -e1[1], -e2[1]],
                  [m * rho ** 2, -cross(rear - c, e1), -cross(front - c, e2)]])
    b = np.array([m * w * w * c[0] + FA * roll[0], m * w * w * c[1] + FA * roll[1],
                  FA * cross(front - c, roll)])
    return np.linalg.solve(A, b)


@pytest.fixture
def ex():
    return CarExplorer(display="agg", **{"drive force (N)": 2000.0})     # the drive of Fig 6.6


@pytest.mark.parametrize("vals", [
    {},
    {"speed (m/s)": 12.0, "turn radius (m)": 30.0},
    {"drive force (N)": -3000.0, "centre of mass ε (× L)": 0.7, "radius of gyration (m)": 2.0},
    {"mass (kg)": 2000.0, "speed (m/s)": 0.0},
])
def test_tyre_forces_match_newton_euler(ex, vals):
    ex.set(**vals)
    v = ex.values
    wd, mu1, mu2 = newton_euler(v["mass (kg)"], v["radius of gyration (m)"], v["turn radius (m)"],
                                v["centre of mass ε (× L)"], v["speed (m/s)"], v["drive force (N)"])
    r = ex.readout_values
    assert ex.message == ""
    assert r["yaw acceleration ω̇"] == pytest.approx(wd, rel=1e-9, abs=1e-12)
    assert r["rear tyre force μ₁"] == pytest.approx(mu1, rel=1e-9, abs=1e-9)
    assert r["front tyre force μ₂"] == pytest.approx(mu2, rel=1e-9, abs=1e-9)
    # drawn tyre lines: the rear force acts along the rear axle through the rear contact, which the
    # drawing puts at the origin (the ICR at (-d, 0)); the front force through the front contact
    # (0, L), along the front axle, towards or away from the ICR
    els = elements(ex.picture())
    d = v["turn radius (m)"]
    rear_line = parts(els["R₁μ₁"], "path")[0]["xy"]
    front_line = parts(els["R₂μ₂"], "path")[0]["xy"]
    # the rear force's line is the rear axle line y = 0 through the rear contact (0, 0) and the ICR
    for x, y in rear_line:
        assert y == pytest.approx(0.0, abs=1e-3)
    assert on_line((-d, 0.0), *front_line, tol=1e-4) and on_line((0.0, L), *front_line, tol=1e-4)
    # its arrow: μ₁ at 1 mm/N, centred on the rear contact, pointing along the force (sign of μ₁)
    pic = ex.picture()
    x0, x1, y0, y1 = pic["box"]
    kx = (pic["size"][0] - pic["margin"][0] - pic["margin"][1]) / (x1 - x0)       # pixels per metre
    for el, mu, at, direction in ((els["R₁μ₁"], mu1, (0.0, 0.0), (1.0, 0.0)),
                                  (els["R₂μ₂"], mu2, (0.0, L), np.array([d, L]) / math.hypot(d, L))):
        arrows = parts(el, "arrow")
        if not arrows:
            assert abs(mu) * 1e-3 * kx < 2.0           # shorter than 2 px: not drawn
            continue
        (a,) = arrows
        vec = np.array([a["dx"], a["dy"]]) / kx
        assert vec == pytest.approx(1e-3 * mu * np.asarray(direction), abs=1e-3)
        assert np.array([a["x"], a["y"]]) + vec / 2 == pytest.approx(at, abs=1e-3)


def test_more_speed_more_tyre_force(ex):
    ex.set(**{"drive force (N)": 0.0})
    f1 = ex.readout_values["rear tyre force μ₁"]
    ex.controls["speed (m/s)"].value = 8.0
    assert abs(ex.readout_values["rear tyre force μ₁"]) > abs(f1)
    assert ex.readout_values["steering angle"] == pytest.approx(math.degrees(math.atan2(L, 8.0)))


def test_the_centre_of_mass_control_says_its_unit_and_range_in_words():
    """Its label is symbol and unit (wheelbases), its meaning and range on hover; "COM" is nowhere on screen,
    not even in the message that refuses a value beyond the rear axle."""
    from planargeo.widgets.car import EPS

    ex = CarExplorer(display="agg")
    w = ex.controls[EPS]
    assert w.description == "ε (× L)" and (w.min, w.max) == (0.0, 1.0)
    assert "centre of mass" in w.tooltip and "front axle" in w.tooltip and "rear axle" in w.tooltip
    assert 310 - 7 * len(w.description) - 90 >= 120             # the track a student drags (as for the others)
    ex.set(**{EPS: 1.5})
    assert ex.values[EPS] == 0.45 and ex.message and "centre of mass" in ex.message
    assert all("COM" not in t for t in (ex.message, w.description, w.tooltip, *ex.readout_values))
