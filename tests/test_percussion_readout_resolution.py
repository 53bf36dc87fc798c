"""The percussion explorer reads round-off as 0 (the student's review).

After drags the readout said "pole x −1.468e-07 m": round-off of the pole's slider value set
from a dragged axis.  The scene is about 1 m across; its numbers below 0.1 mm (``zero_tol``)
now read "0 m" (never −0); the others keep their 4 significant digits, as before.  Only the
text changes: the values are the state's own.
"""
from __future__ import annotations

import math
import re

import numpy as np
import pytest

from planargeo.widgets.percussion import PRESETS, PercussionExplorer

#: the rows in metres (the explorer's words data)
LENGTHS = ("pole x", "pole y", "radius of gyration ρ", "centre of mass", "pole", "d = |pole − c|",
           "r = ρ²/d (5.68)", "l = d + ρ²/d (5.67)", "centre of percussion", "sweet spot of the grip",
           "impact at", "pole distance from grip")
NUMBER = re.compile(r"[-−]?(?:\d+\.?\d*|\.\d+)(?:×10[⁻]?[⁰¹²³⁴⁵⁶⁷⁸⁹]+)?")
_POWER = str.maketrans("⁻⁰¹²³⁴⁵⁶⁷⁸⁹", "-0123456789")


def _number(t: str) -> float:
    """A readout number (``8.651×10⁻⁴`` too) as a float."""
    mant, _, power = t.replace("−", "-").partition("×10")
    return float(mant) * 10.0 ** int(power.translate(_POWER)) if power else float(mant)


@pytest.fixture
def ex():
    return PercussionExplorer(display="agg")


def test_round_off_left_by_a_drag_reads_zero(ex):
    ex.set(**{"pole x": -1.468e-07, "pole y": 2.3e-06})
    assert ex.message == ""
    assert ex.readout_values["pole x"] == -1.468e-07           # the state is not changed
    assert ex.readout_strings["pole x"] == "0 m" and ex.readout_strings["pole y"] == "0 m"
    assert ex.readout_strings["pole"] == "(0, 0) m"
    # d = |pole − c| with c on the x axis: the centre of mass's x, to 4 digits
    cx = ex.readout_values["centre of mass"][0]
    assert ex.readout_strings["d = |pole − c|"] == f"{float(f'{cx:.4g}'):g} m"


@pytest.mark.parametrize("x, text", [(8.651e-04, "8.651×10⁻⁴ m"), (-4.9e-05, "0 m"), (5.1e-05, "0 m"),
                                     (0.02808, "0.02808 m"), (-0.06461, "-0.06461 m"), (1.092, "1.092 m")])
def test_a_length_reads_to_a_tenth_of_a_millimetre_and_four_digits(ex, x, text):
    ex.set(**{"pole x": x})
    assert ex.readout_strings["pole x"] == text


def test_no_length_reads_round_off_after_many_drags(ex):
    rng = np.random.default_rng(7)
    seen = 0
    for shape in list(PRESETS)[:3]:
        ex.set(shape=shape, drive="acceleration pole")
        for _ in range(8):
            hs = {h.name: h for h in ex.handles()}
            for name in ("axis (point)", "axis (direction)", "a"):
                at = hs[name].where()
                if at is None:
                    continue
                to = (float(at[0]) + rng.normal(0, 0.15), float(at[1]) + rng.normal(0, 0.15))
                if rng.random() < 0.3:                  # back onto the x axis: components near 0
                    to = (to[0], 0.0)
                ex.drag(name, tuple(map(float, at)), to, steps=2)
                for k in LENGTHS:
                    if k not in ex.readout_strings:
                        continue
                    text, value = ex.readout_strings[k], ex.readout_values[k]
                    assert "e-" not in text and not re.search(r"[-−]0(?:\.0*)?(?=[ ,)])", text + " "), (k, text)
                    if isinstance(value, str):
                        continue
                    want = np.ravel(np.asarray(value, dtype=float))
                    shown = [_number(t) for t in NUMBER.findall(text)]
                    assert len(shown) == len(want), (k, text, value)
                    for s, v in zip(shown, want):    # 0 below 0.1 mm, else to 4 digits
                        if math.isfinite(v):
                            assert abs(s - v) <= max(1e-4, 5e-4 * abs(v)), (k, text, value)
                    seen += 1
    assert seen > 100
