"""A notebook shows a point, line, conic, twist, wrench or inertia as a picture (planargeo.draw.notebook).

The picture is the same kind the explorers and the gallery draw (one geometry, one SVG writer:
matplotlib).  Checked against hand-derived positions: where the element's parts sit relative to
the origin cross, which the picture places at (0, 0).
"""
from __future__ import annotations

import math
import subprocess
import sys
import xml.etree.ElementTree as ET

import numpy as np
import pytest

from planargeo.draw.notebook import element_picture, element_svg
from planargeo.errors import InputError
from planargeo.geometry.elements import Conic, Line, Point
from planargeo.screws.inertia import Inertia
from planargeo.screws.twists import Twist, Wrench

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
    "inertia": Inertia.from_mass(2.0, (1.0, 0.0), radius_of_gyration=0.5),
}


def _el(pic, id):
    return next(e for e in pic.to_dict()["elements"] if e["id"] == id)


def _parts(pic, id, kind):
    return [p for p in _el(pic, id)["parts"] if p["p"] == kind]


@pytest.mark.parametrize("name", list(OBJECTS))
def test_every_element_is_a_picture_with_the_origin_in_view(name):
    pic = element_picture(OBJECTS[name])
    d = pic.to_dict()
    x0, x1, y0, y1 = d["box"]
    assert x0 < 0 < x1 and y0 < 0 < y1                   # the origin cross is in view
    assert pic.title and all(e["desc"] for e in d["elements"])
    assert element_svg(OBJECTS[name]) == element_svg(OBJECTS[name])    # deterministic
    assert ET.fromstring(element_svg(OBJECTS[name]).encode()).tag.endswith("svg")


def test_a_finite_point_is_drawn_where_it_is():
    pic = element_picture(Point.from_xy(1.0, 2.0))
    (m,) = _parts(pic, "P", "mark")
    assert (m["x"], m["y"]) == pytest.approx((1.0, 2.0))
    assert pic.title == "P = (1, 2)"


def test_an_ideal_point_is_an_edge_arrow_on_the_side_where_it_lies():
    """Point.at_infinity((0, 1)) lies straight up: its arrow sits at the top edge."""
    pic = element_picture(Point.at_infinity((0.0, 1.0)))
    (a,) = _parts(pic, "P", "arrow")
    x0, x1, y0, y1 = pic.box
    assert a["y"] > (y0 + y1) / 2 + 0.3 * (y1 - y0)
    assert "at infinity" in pic.title


def test_a_line_is_clipped_to_the_view_on_its_equation():
    """y = 1 along +x: both ends of the drawn segment have y = 1 and lie on the view's sides."""
    pic = element_picture(Line.from_point_direction((0.0, 1.0), (1.0, 0.0)))
    (seg,) = _parts(pic, "l", "path")
    (xa, ya), (xb, yb) = seg["xy"]
    assert ya == pytest.approx(1.0) and yb == pytest.approx(1.0)
    assert sorted([xa, xb]) == pytest.approx([pic.box[0], pic.box[1]])


def test_a_force_is_its_line_of_action_with_its_sense():
    """F = (0, 2) through (2, 0): the line x = 2, the arrow pointing up."""
    pic = element_picture(Wrench.force((2.0, 0.0), (0.0, 2.0)))
    (seg,) = _parts(pic, "f", "path")
    assert [p[0] for p in seg["xy"]] == pytest.approx([2.0, 2.0])
    (a,) = _parts(pic, "f", "arrow")
    assert a["dx"] == pytest.approx(0.0, abs=1e-9) and a["dy"] > 0
    assert pic.title == "f: F = 2 through (2, 0)"


def test_line_at_infinity_and_couple_are_named():
    assert "line at infinity" in element_picture(Line.at_infinity()).title
    pic = element_picture(Wrench.couple(-2.0))
    assert pic.title == "f: pure couple, τ = -2"
    (g,) = _parts(pic, "f", "glyph")
    assert g["ccw"] is False                              # τ < 0 turns clockwise


def test_inertia_is_its_circle_of_gyration():
    """m 2 at (1, 0) with ρ 0.5: the dashed circle of radius ρ about c (10.2.3)."""
    pic = element_picture(OBJECTS["inertia"])
    (e,) = _parts(pic, "I", "ellipse")
    assert (e["x"], e["y"]) == pytest.approx((1.0, 0.0))
    a, b, c, d = e["m"]
    assert abs(a * d - b * c) == pytest.approx(0.25)      # area factor ρ²
    assert np.linalg.svd([[a, b], [c, d]])[1] == pytest.approx([0.5, 0.5])
    assert _el(pic, "I")["dash"]
    assert pic.title == "I: m = 2, c = (1, 0), ρ = 0.5"


def test_imaginary_conic_is_its_sign_flipped_partner():
    """x² + (y − 1)² = −1 is drawn as x² + (y − 1)² = 1 (thesis 10.2.3), dashed."""
    pic = element_picture(OBJECTS["imaginary circle"])
    (e,) = _parts(pic, "C", "ellipse")
    assert (e["x"], e["y"]) == pytest.approx((0.0, 1.0))
    assert np.linalg.svd(np.reshape(e["m"], (2, 2)))[1] == pytest.approx([1.0, 1.0])
    assert _el(pic, "C")["dash"] and "10.2.3" in _el(pic, "C")["desc"]


def test_twist_shows_pole_and_sense_of_rotation():
    for w, ccw in ((3.0, True), (-1.0, False)):
        pic = element_picture(Twist.rotation((1.0, 2.0), w))
        (m,) = _parts(pic, "v", "mark")
        (g,) = _parts(pic, "v", "glyph")
        assert (m["x"], m["y"]) == pytest.approx((1.0, 2.0)) and g["ccw"] is ccw
    assert "translation" in element_picture(Twist.translation((1.0, 0.0))).title
    assert "zero twist" in element_picture(Twist([0.0, 0.0, 0.0])).title


def test_batches_and_strangers():
    assert element_svg(Twist(np.zeros((2, 3)) + [1.0, 0.0, 1.0])) is None
    with pytest.raises(InputError, match="obj must be a single element"):
        element_picture(Wrench(np.ones((2, 3))))
    with pytest.raises(InputError, match="obj must be a Point"):
        element_picture("P")


def test_import_planargeo_in_ipython_shows_elements_as_svg():
    """The math classes do not draw; inside IPython, importing planargeo registers the drawing."""
    code = (
        "from IPython.core.interactiveshell import InteractiveShell\n"
        "import sys\n"
        "shell = InteractiveShell.instance()\n"
        "import planargeo as pg\n"
        "assert 'matplotlib' not in sys.modules\n"
        "data, _ = shell.display_formatter.format(pg.Twist.rotation((1.0, 2.0), 3.0))\n"
        "assert data['image/svg+xml'].lstrip().startswith('<?xml'), data.keys()\n"
        "data, _ = shell.display_formatter.format(pg.Twist([[1.0, 0, 1], [0, 1, 1]]))\n"
        "assert 'image/svg+xml' not in data and 'text/plain' in data\n"
        "print('ok')\n")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300)
    assert r.returncode == 0 and r.stdout.strip() == "ok", r.stderr[-2000:]
