"""Every slider of these explorers keeps a track a student can drag: its label, about 7 px a
character at 12 px, beside a 310 px slider with ~90 px for its value and margins, leaves at least
100 px (120 px for the labels shortened to symbol and unit, their meaning said on hover).

Measured in a browser (Voila, chromium): "g (m/s²)" left a 161 px track, "rod length l (m)" 113 px,
"crank speed ψ̇ at t = 0 (rad/s)" 21 px."""
import re
import unicodedata

import pytest

from planargeo.widgets.impulse import ImpulseExplorer
from planargeo.widgets.percussion import PercussionExplorer
from planargeo.widgets.projective import ProjectiveExplorer
from planargeo.widgets.screw_sum import ScrewSumExplorer
from planargeo.widgets.slider_crank import SliderCrankExplorer
from planargeo.widgets.subspace import SubspaceExplorer
from planargeo.widgets.trees import TreeExplorer


def label_text(w) -> str:
    """The slider's label as the page shows it (an HTML label's tags taken out)."""
    return re.sub(r"<[^>]*>", "", w.description) if w.description_allow_html else w.description


def track_px(w) -> float:
    """The slider's track left beside its label (px, a browser's rough measure)."""
    shown = sum(1 for ch in label_text(w) if not unicodedata.combining(ch))
    return float(w.layout.width.removesuffix("px")) - 7.0 * shown - 90.0


#: the controls whose long labels squeezed their tracks: (explorer, control, words its tooltip says)
SHORTENED = [(SliderCrankExplorer, "crank angle (deg)", "crank angle"),
             (SliderCrankExplorer, "crank speed", "crank speed"),
             (PercussionExplorer, "angular accel. α", "angular acceleration"),
             (ImpulseExplorer, "t", "time after the blow"),
             (SubspaceExplorer, "rho", "radius of gyration")]


@pytest.mark.parametrize("cls", [SliderCrankExplorer, PercussionExplorer, ImpulseExplorer, SubspaceExplorer,
                                 TreeExplorer, ScrewSumExplorer, ProjectiveExplorer])
def test_every_slider_keeps_a_track(cls):
    ex = cls(display="agg")
    sliders = {k: w for k, w in ex.controls.items() if hasattr(w, "readout_format")}
    assert sliders
    assert {k: track_px(w) for k, w in sliders.items() if track_px(w) < 100.0} == {}


@pytest.mark.parametrize("cls, name, meaning", SHORTENED)
def test_a_shortened_label_is_symbol_and_unit_its_meaning_on_hover(cls, name, meaning):
    ex = cls(display="agg")
    w = ex.controls[name]                      # the control keeps its name (ex.values, notebooks)
    assert track_px(w) >= 120.0, w.description
    assert meaning in w.tooltip and label_text(w).split(" (")[0] in w.tooltip
    assert name in ex.values
