"""Projective playground: a construction point off the view is named at its edge arrow."""
import numpy as np
import pytest

from planargeo.geometry.conics import tangents_from_point
from planargeo.geometry.projective import is_ideal
from planargeo.widgets import ProjectiveExplorer


def _texts(el):
    return [q["text"] for q in el["parts"] if q["p"] == "text"]


@pytest.mark.parametrize("values", [{"conic": "parabola"}, {"conic": "parabola", "P x": -2.0, "P y": -1.0}])
def test_off_view_construction_points_name_themselves(values):
    ex = ProjectiveExplorer(display="agg")
    ex.set(**values)
    assert ex.message == ""
    x0, x1, y0, y1 = ex.limits
    # where the contacts are, from the geometry directly (not the picture)
    _, X = tangents_from_point(ex.state["C"], ex.state["P"])
    off = []
    for k, p in enumerate(np.asarray(X, float)):
        xy = None if is_ideal(p) else (-p[1] / p[2], p[0] / p[2])
        if xy is None or not (x0 <= xy[0] <= x1 and y0 <= xy[1] <= y1):
            off.append(k)
    if values["conic"] == "parabola":
        assert off == [0]                       # X₁ at about (-0.44, 14.5) m, as the student saw
    els = {e["id"]: e for e in ex.picture()["elements"]}
    for k in range(2):
        el = els[f"contact {k + 1}"]
        arrows = [q for q in el["parts"] if q["p"] == "arrow"]
        sym = "X" + "₁₂"[k]
        if k in off:
            assert arrows and any(t.startswith(sym) and t.endswith("(off view)") for t in _texts(el)), _texts(el)
        else:
            assert not arrows and _texts(el) == []      # in view: a plain marker, as before


def test_pole_of_m_still_names_itself():
    ex = ProjectiveExplorer(display="agg")
    ex.set(conic="parabola")
    el = {e["id"]: e for e in ex.picture()["elements"]}["pole of M"]
    assert _texts(el) == ["pole of M (off view)"]
