"""Every explorer's readout table says each unit once, at its default state (planargeo.widgets.readout).

The rule (readout.py's module docstring): a row whose numbers share one unit -- a number, a vector
or a point -- has numbers only in its value column and the unit in the unit column; a vector whose
components differ in unit names each after its number and leaves the unit column empty.  A number
never stands beside a unit written ``1/…`` (``0 1/kg`` reads as two numbers), and a number between
0.001 and 100000 is never in scientific notation.  The table says what the row's plain text
(``readout_strings``) says, and its numbers are the readout's values to 4 significant digits.
"""
from __future__ import annotations

import html
import math
import re

import numpy as np
import pytest

import planargeo.widgets as W
from planargeo.widgets.readout import is_numeric

ROW = re.compile(r"<tr><td[^>]*>(.*?)</td><td[^>]*>(.*?)</td><td[^>]*>(.*?)</td></tr>")
NUMBER = re.compile(r"[-−]?(?:\d+\.?\d*|\.\d+)(?:e[+-]\d+)?")
SCIENTIFIC = re.compile(r"[-−]?\d(?:\.\d+)?e[+-]\d+")


def _rows(ex) -> list[tuple[str, str, str]]:
    return [tuple(html.unescape(c) for c in r) for r in ROW.findall(ex.readout.value)]


def _component_units(value: str) -> list[str] | None:
    """The units written after the components of ``(a u, b v, ...)``; None when some has none."""
    if not (value.startswith("(") and value.endswith(")")):
        return None
    units = []
    for comp in value[1:-1].split(", "):
        m = re.fullmatch(r"[-−]?[\d.e+-]+ (\S.*)", comp)
        if m is None:
            return None
        units.append(m[1])
    return units


#: units a value column must not end with (besides the explorer's own)
UNITS = {"m", "m/s", "m/s²", "rad/s", "rad/s²", "N", "N·m", "N·s", "kg", "kg·m²", "J", "W", "s", "°", "g"}


def _units_of(ex) -> set[str]:
    out = set(UNITS)
    for u in ex.units.values():
        out.update(u if isinstance(u, tuple) else (u,))
    return {u for u in out if u not in ("", "—", "-")}


def _problems(name: str, ex) -> list[str]:
    out = []
    units = _units_of(ex)
    rows = _rows(ex)
    texts = [(k, t) for k, t in ex.readout_strings.items()]
    values = [(k, v) for k, v in ex.readout_values.items() if not str(k).startswith("_")]
    assert len(rows) == len(texts) == len(values), (name, len(rows), len(texts), len(values))
    for (label, value, unit), (key, text), (_k, v) in zip(rows, texts, values):
        where = f"{name} {key!r}: {value!r} | {unit!r}"
        per = _component_units(value)
        mixed = per is not None and len(set(per)) > 1
        if per is not None and not mixed:
            out.append(f"{where}: one unit said after every component")
        if mixed and unit:
            out.append(f"{where}: a unit said after the components and in the unit column")
        if not mixed and any(value.endswith(" " + u) for u in units):
            out.append(f"{where}: a common unit in the value column")
        if re.search(r"\d 1/", value):
            out.append(f"{where}: a number beside a unit written 1/…")
        for tok in SCIENTIFIC.findall(value):
            if 1e-3 <= abs(float(tok.replace("−", "-"))) < 1e5:
                out.append(f"{where}: {tok} in scientific notation")
        if unit and not re.search(r"\d|∞", value):
            out.append(f"{where}: a unit after words")
        if text != (f"{value} {unit}" if unit else value):
            out.append(f"{where}: the table and the text {text!r} differ")
        if is_numeric(v):                       # the numbers shown are the values, rounded
            want = [float(x) for x in np.ravel(np.asarray(v, dtype=float))]
            if all(map(math.isfinite, want)):
                shown = [float(t.replace("−", "-")) for t in NUMBER.findall(value)]
                scale = max(map(abs, want))
                if len(shown) != len(want) or any(abs(s - x) > 5e-4 * abs(x) + 1e-9 * (scale + 1.0)
                                                  for s, x in zip(shown, want)):
                    out.append(f"{where}: shows {shown} for {want}")
    return out


@pytest.mark.parametrize("name", list(W.EXPLORERS))
def test_every_unit_is_said_once_at_the_default_state(name):
    ex = getattr(W, name)(display="agg")
    assert ex.message == "", ex.message
    problems = _problems(name, ex)
    assert not problems, "\n".join(problems)


def test_points_read_like_every_other_row():
    """A point (articulated pole a, the impulse's velocity pole) reads (x, y) | m, like the
    percussion explorer's centre of mass; one at infinity is words, with no unit."""
    rows = {r[0]: r[1:] for r in _rows(W.ArticulatedExplorer(display="agg"))}
    assert rows["pole a"] == ("(0, -0.8)", "m")
    ex = W.ImpulseExplorer(display="agg")
    assert dict((r[0], r[1:]) for r in _rows(ex))["velocity pole"] == ("(0, 0)", "m")
    assert ex.readout_strings["velocity pole"] == "(0, 0) m"            # the row's text is unchanged
    ex.set(support="free", **{"strike y": 0.0, "strike angle": 0.0})   # along the bat, through its centre
    rows = dict((r[0], r[1:]) for r in _rows(ex))
    assert rows["velocity pole"][0].startswith("at infinity (direction (") and rows["velocity pole"][1] == ""
    assert not _problems("ImpulseExplorer", ex)


def test_large_numbers_and_reciprocal_units_read_plainly():
    car = W.CarExplorer(display="agg")
    k = car.readout_values["kinetic energy K"]
    assert 1e4 <= k < 1e5
    shown = dict((r[0], r[1:]) for r in _rows(car))["kinetic energy K"]
    assert shown[1] == "J" and "e" not in shown[0] and float(shown[0]) == pytest.approx(k, rel=5e-4)
    split = W.SplittingExplorer(display="agg")
    assert split.readout_strings["row 3 of Λᵢ⁻¹"] == "(0 kg⁻¹·m⁻¹, 0 kg⁻¹·m⁻¹, 2 kg⁻¹·m⁻²)"
