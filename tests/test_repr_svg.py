"""Twist, Wrench, Inertia, Point, Line and Conic show themselves as small SVG drawings (issue 13).

Checked without matplotlib: the text parses as XML, is the same every time, every
text is at least 11 px, and the drawing is where the element is: positions are read
back from the SVG relative to the origin mark ``O`` (a grey cross) and compared with
the element's own coordinates (hand-derived below).
"""
from __future__ import annotations

import math
import xml.etree.ElementTree as ET

import numpy as np
import pytest

from planargeo.geometry.elements import Conic, Line, Point
from planargeo.geometry.svg import SvgPanel, conic_svg, point_svg
from planargeo.screws.inertia import Inertia
from planargeo.screws.twists import Twist, Wrench
from planargeo.errors import InputError

NS = "{http://www.w3.org/2000/svg}"

OBJECTS = {
    "point": Point.from_xy(1.0, 2.0),
    "ideal point": Point.at_infinity((0.0, 1.0)),
    "line": Line.from_point_direction((0.0, 1.0), (1.0, 0.0)),
    "line at infinity": Line.at_infinity(),
    "circle": Conic.circle((1.0, 0.0), 2.0),
    "ellipse": Conic.ellipse((0.0, 1.0), (2.0, 1.0), 0.3),
    "hyperbola": Conic.hyperbola((0.0, 0.0), (1.0, 0.5)),
    "parabola": Conic.parabola((0.0, 0.0), 0.5),
    "imaginary circle": Conic.circle((0.0, 1.0), 1.0, imaginary=True),
    "degenerate": Conic(np.diag([1.0, -1.0, 0.0])),
    "rotation": Twist.rotation((1.0, 2.0), 3.0),
    "clockwise rotation": Twist.rotation((-1.0, 0.5), -1.0),
    "translation": Twist.translation((0.0, 2.0)),
    "zero twist": Twist([0.0, 0.0, 0.0]),
    "force": Wrench.force((2.0, 0.0), (0.0, 2.0)),
    "couple": Wrench.couple(-2.0),
    "zero wrench": Wrench([0.0, 0.0, 0.0]),
    "inertia": Inertia.from_mass(2.0, (1.0, 0.0), radius_of_gyration=0.5),
}


def _root(svg: str):
    return ET.fromstring(svg)


def _texts(root):
    return [t for t in root.iter(f"{NS}text")]


def _origin_px(root):
    """Pixel centre of the origin cross (the two short grey polylines)."""
    xs, ys = [], []
    for pl in root.iter(f"{NS}polyline"):
        if pl.get("stroke") == "#7F7F7F":
            pts = [tuple(map(float, p.split(","))) for p in pl.get("points").split()]
            xs += [p[0] for p in pts]
            ys += [p[1] for p in pts]
    return (min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2


def _circles(root):
    return [(float(c.get("cx")), float(c.get("cy"))) for c in root.iter(f"{NS}circle")]


@pytest.mark.parametrize("name", list(OBJECTS))
def test_valid_deterministic_legible(name):
    obj = OBJECTS[name]
    svg = obj._repr_svg_()
    assert svg == obj._repr_svg_()                      # deterministic
    root = _root(svg)                                    # valid XML
    assert root.tag == f"{NS}svg"
    texts = _texts(root)
    assert texts, "a drawing names what it shows"
    assert all(float(t.get("font-size")) >= 11 for t in texts)
    W = float(root.get("width"))
    for t in texts:                                      # estimated text box inside the drawing
        x, n = float(t.get("x")), len(t.text)
        half = 0.31 * 12 * n
        left = {"start": x, "middle": x - half, "end": x - 2 * half}[t.get("text-anchor")]
        assert -1 <= left and left + 2 * half <= W + 1, (t.text, left, W)
    assert root.find(f"{NS}title").text


def test_a_finite_point_is_drawn_where_it_is():
    root = _root(Point.from_xy(1.0, 2.0)._repr_svg_())
    ox, oy = _origin_px(root)
    (px, py), = _circles(root)
    # screen y points down: the point (1, 2) is right of and above O, twice as far up as right
    assert px > ox and py < oy
    assert math.isclose((oy - py) / (px - ox), 2.0, rel_tol=1e-3)
    assert "P = (1, 2)" in [t.text for t in _texts(root)]


def test_ideal_point_is_an_arrow_in_its_direction():
    svg = Point.at_infinity((0.0, 1.0))._repr_svg_()     # straight up
    root = _root(svg)
    line = root.find(f".//{NS}line")
    x1, y1, x2, y2 = (float(line.get(k)) for k in ("x1", "y1", "x2", "y2"))
    assert math.isclose(x1, x2, abs_tol=1e-6) and y2 < y1   # points up on screen
    assert "at infinity" in svg


def test_line_points_satisfy_the_line_equation():
    root = _root(Line.from_point_direction((0.0, 1.0), (1.0, 0.0))._repr_svg_())   # y = 1
    ox, oy = _origin_px(root)
    long = max((pl for pl in root.iter(f"{NS}polyline") if pl.get("stroke") == "#E69F00"),
               key=lambda pl: len(pl.get("points")))
    ys = {round(float(p.split(",")[1]), 6) for p in long.get("points").split()}
    assert len(ys) == 1 and ys.pop() < oy                 # horizontal, above O


def test_line_at_infinity_and_couple_are_named():
    assert "line at infinity" in Line.at_infinity()._repr_svg_()
    svg = Wrench.couple(-2.0)._repr_svg_()
    assert "line at infinity" in svg and "τ = -2" in svg


def test_inertia_is_its_circle_of_gyration():
    """m 2 at (1, 0) with ρ 0.5: the dashed circle has radius ρ about c; |c| / ρ = 2 (10.2.3)."""
    root = _root(OBJECTS["inertia"]._repr_svg_())
    ox, oy = _origin_px(root)
    (cx, cy), = _circles(root)
    dashed = [pl for pl in root.iter(f"{NS}polyline") if pl.get("stroke-dasharray")]
    pts = np.array([[float(v) for v in p.split(",")] for p in dashed[0].get("points").split()])
    r = np.hypot(pts[:, 0] - cx, pts[:, 1] - cy)
    assert np.ptp(r) < 0.02 * r.mean()
    assert math.isclose(math.hypot(cx - ox, cy - oy) / r.mean(), 2.0, rel_tol=1e-3)
    assert "I: m = 2, c = (1, 0), ρ = 0.5" in [t.text for t in _texts(root)]


def test_imaginary_conic_is_its_sign_flipped_partner():
    """x² + (y − 1)² = −1 is drawn as x² + (y − 1)² = 1 (thesis 10.2.3), dashed, with a note."""
    svg = OBJECTS["imaginary circle"]._repr_svg_()
    root = _root(svg)
    (cx, cy), = _circles(root)
    ox, oy = _origin_px(root)
    dashed = [pl for pl in root.iter(f"{NS}polyline") if pl.get("stroke-dasharray")]
    pts = np.array([[float(v) for v in p.split(",")] for p in dashed[0].get("points").split()])
    r = np.hypot(pts[:, 0] - cx, pts[:, 1] - cy).mean()
    assert math.isclose(math.hypot(cx - ox, cy - oy) / r, 1.0, rel_tol=1e-3)   # centre (0, 1), radius 1
    assert "10.2.3" in svg and "imaginary" in svg


def test_twist_shows_the_sense_of_rotation():
    ccw = _root(Twist.rotation((0.0, 0.0), 1.0)._repr_svg_())
    cw = _root(Twist.rotation((0.0, 0.0), -1.0)._repr_svg_())
    assert ET.tostring(ccw) != ET.tostring(cw)
    assert "translation" in Twist.translation((1.0, 0.0))._repr_svg_()
    assert "zero twist" in Twist([0.0, 0.0, 0.0])._repr_svg_()


def test_batches_fall_back_to_text():
    assert Twist(np.zeros((2, 3)) + [1.0, 0.0, 1.0])._repr_svg_() is None
    assert Wrench(np.ones((2, 3)))._repr_svg_() is None


def test_bad_input_is_named():
    with pytest.raises(InputError, match="p must be a single"):
        point_svg(np.ones((2, 3)))
    with pytest.raises(InputError, match="C must be finite"):
        conic_svg(np.full((3, 3), np.nan))
    with pytest.raises(InputError, match="box"):
        SvgPanel((1, 0, 0, 1), "bad")


def test_geometry_does_not_import_matplotlib():
    import ast
    from pathlib import Path

    import planargeo.geometry.svg as mod

    tree = ast.parse(Path(mod.__file__).read_text(encoding="utf-8"))
    names = [a.name for n in ast.walk(tree) if isinstance(n, ast.Import) for a in n.names]
    names += [n.module or "" for n in ast.walk(tree) if isinstance(n, ast.ImportFrom)]
    assert not [n for n in names if n.startswith("matplotlib")]
