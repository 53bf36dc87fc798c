"""The pictures' words for a force and a point keep their geometry at the ends of the floats (issue 23).

* A force ``[fx, fy, τ]`` is told by its size and the foot of the origin on its line, ``τ ẑ × f / |f|²``.
  Written with ``F * F`` it underflowed for a force of 1e-300 N (ZeroDivisionError: the Splitting and
  Subspace pictures could not be drawn).  The foot does not depend on the force's size, so a slider
  set to 1e-300 must tell the same line as 1 (linearity), and the closed form of the line the user set.
* A pole ``[a, b, w]`` is at ``(−b/w, a/w)``: with a blow through the centre's height but 5e-324 off,
  ``w`` is subnormal and the division overflowed (a RuntimeWarning, "∞" on the picture).  It is now
  "far off", in the direction the closed form ``y_P − y_c = ρ² / (−y)`` gives.

All through the explorers' public ``set`` and ``picture``, warnings raised as errors.
"""
from __future__ import annotations

import math
import re
import warnings

import pytest

from planargeo.widgets import ImpulseExplorer, SplittingExplorer, SubspaceExplorer

THROUGH = re.compile(r"(?P<F>\S+) N, through \((?P<x>\S+), (?P<y>\S+)\) m")


def _desc(pic, id_: str) -> str:
    found = [e["desc"] for e in pic["elements"] if e["id"] == id_]
    assert len(found) == 1, (id_, [e["id"] for e in pic["elements"]])
    return found[0]


def _line(desc: str) -> tuple[float, float]:
    m = THROUGH.search(desc)
    assert m, desc
    return float(m["x"]), float(m["y"])


def _drawn(ex, **values) -> dict:
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        ex.set(**values)
        assert ex.message == "", ex.message
        return ex.picture()


@pytest.mark.parametrize("tau", [-1e-300, 1e-300, -1e-310])
def test_a_tiny_couple_on_the_splitting_picture_tells_the_same_line_as_a_unit_one(tau):
    ex = SplittingExplorer(display="agg")
    assert ex.values["g (m/s²)"] == 0.0          # at rest, no gravity: every force is τ times one shape
    ref = _line(_desc(_drawn(ex, **{"couple τ (N·m)": -1.0}), "f"))
    assert ref == _line(_desc(_drawn(ex, **{"couple τ (N·m)": 2.0}), "f"))   # the line has no size
    pic = _drawn(ex, **{"couple τ (N·m)": tau})
    assert ex.values["couple τ (N·m)"] == tau                                 # computed, not replaced
    assert _line(_desc(pic, "f")) == ref


@pytest.mark.parametrize("F", [1e-300, -1e-300])
def test_a_tiny_force_on_the_subspace_picture_keeps_its_line(F):
    ex = SubspaceExplorer(display="agg", show="f = TQ + Rμ")
    x0, y0, a = 2.0, 0.5, 30.0
    pic = _drawn(ex, **{"force x": x0, "force y": y0, "force angle": a, "F": F})
    assert ex.values["F"] == F
    # closed form: the foot of the origin on the line through (x0, y0) along angle a
    u = (math.cos(math.radians(a)), math.sin(math.radians(a)))
    s = x0 * u[0] + y0 * u[1]
    fx, fy = _line(_desc(pic, "f"))
    assert fx == pytest.approx(x0 - s * u[0], abs=1e-4) and fy == pytest.approx(y0 - s * u[1], abs=1e-4)
    # its parts along the joint and into it: the same lines as for a force of 1 N (linearity)
    tiny = {k: _line(_desc(pic, k)) for k in ("TQ", "Rmu")}
    one = _drawn(SubspaceExplorer(display="agg", show="f = TQ + Rμ"),
                 **{"force x": x0, "force y": y0, "force angle": a, "F": 1.0})
    assert tiny == {k: _line(_desc(one, k)) for k in ("TQ", "Rmu")}


POLE = re.compile(r"ω = \S+ rad/s, (?P<where>.*)$")


def _pole_words(pic) -> str:
    d = next(e["desc"] for e in pic["elements"] if e["desc"].startswith("the velocity pole just after"))
    return POLE.search(d)["where"]


def test_a_blow_just_off_the_centre_puts_the_pole_far_off_on_the_right_side():
    """A free door struck along x at height y: it turns with ω ∝ −y about a pole at ``y_c + ρ²/(−y)``
    straight above or below its centre; 5e-324 off the centre line, the pole is far off that way."""
    ex = ImpulseExplorer(display="agg", body="door", support="free")
    pic = _drawn(ex, **{"strike angle": 0.0, "strike y": -0.3})
    rho = ex.readout_values["radius of gyration ρ"]
    m = re.fullmatch(r"at \((?P<x>\S+), (?P<y>\S+)\) m", _pole_words(pic))
    assert m and float(m["y"]) == pytest.approx(rho ** 2 / 0.3, rel=1e-3)  # the closed form, finite
    cx = float(m["x"])
    for y in (-1e-200, 1e-200):
        m = re.fullmatch(r"at \((?P<x>\S+), (?P<y>\S+)\) m", _pole_words(_drawn(ex, **{"strike y": y})))
        assert m and float(m["x"]) == cx and float(m["y"]) == pytest.approx(rho ** 2 / -y, rel=1e-3)
    for y, side in ((-5e-324, 1), (5e-324, -1)):
        pic = _drawn(ex, **{"strike y": y})                 # no overflow warning (raised as an error here)
        assert ex.values["strike y"] == y
        assert _pole_words(pic) == f"far off, direction (0, {side})"
        # the readout (its own words, a point at infinity: a direction up to sign) agrees
        assert ex.readout_values["velocity pole"] in ("at infinity (direction (0, 1))",
                                                      "at infinity (direction (0, -1))")
    # exactly on the centre line: a pure translation, the pole a point at infinity
    assert _pole_words(_drawn(ex, **{"strike y": 0.0})) in ("at infinity, direction (0, 1)",
                                                             "at infinity, direction (0, -1)")


def test_trees_pin_forces_of_a_subnormal_gravity_are_drawn_like_any_other():
    """At rest the pin forces are proportional to g (statics), so the arrows, drawn to the largest,
    are the same for g = 9.81 and for a subnormal g = 1e-310, where 1/fmax overflows."""
    from planargeo.widgets import TreeExplorer

    def arrows(g):
        t = TreeExplorer(display="agg")
        t.set(speed=0.0)
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            t.set(gravity=g)
            pic = t.picture()
        assert t.message == ""
        return {e["id"]: (p["dx"], p["dy"]) for e in pic["elements"] if e["role"] == "reaction"
                for p in e["parts"] if p["p"] == "arrow"}

    big, tiny = arrows(9.81), arrows(1e-310)
    assert big and set(big) == set(tiny)
    for k in big:
        assert tiny[k] == pytest.approx(big[k], rel=1e-3, abs=0.05)
