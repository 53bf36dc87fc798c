"""The app's text matches its buttons (issue 22): every button it names exists, every button is named."""
import json
import re
from pathlib import Path

import ipywidgets as W

from planargeo.widgets import ProjectiveExplorer, SliderCrankExplorer

APP = Path(__file__).resolve().parents[1] / "app" / "planargeo-app.ipynb"


def intro() -> str:
    nb = json.loads(APP.read_text())
    return "".join(nb["cells"][0]["source"])


def buttons(ex) -> set[str]:
    """Descriptions of the explorer's buttons, as laid out on screen."""
    found, todo = set(), [ex.widget]
    while todo:
        w = todo.pop()
        if isinstance(w, W.Button):
            found.add(w.description)
        todo.extend(getattr(w, "children", ()))
    return found


def test_the_intro_names_every_button_and_no_other():
    text = intro()
    named = set(re.findall(r"\*\*([A-Z][A-Za-z0-9]*)\*\*", text))
    still = buttons(ProjectiveExplorer(display="agg"))          # no Play: SVG, PNG, Reset
    moving = buttons(SliderCrankExplorer(display="agg"))        # Play: GIF, and MP4 with ffmpeg
    assert {"Reset", "SVG", "PNG"} <= still and "GIF" not in still and "GIF" in moving
    shown = still | moving
    assert shown - {"MP4"} <= named                             # every button is named
    assert named - {"Play"} <= shown | {"MP4"}                  # and the text names no other
    # MP4 is promised only with its condition, and GIF for the explorers that move
    assert re.search(r"MP4\*\* where the ffmpeg program is installed", text)
    assert "GIF" in text and "Play" in text
