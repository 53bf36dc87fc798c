"""The dots of ψ̇ and ψ̈ show in the slider-crank page (Voila, Chromium) -- the student's review.

At 12-13 px Chromium draws them with DejaVu Sans (system-ui through fontconfig: the font is
there, the marks are in it), each dot one grey pixel against ψ's top: "ψ̈ crank" reads "ψ crank".
No installed font stack draws a larger dot (DejaVu Sans, Serif, Math, Liberation: measured); a
bold symbol does (a 2 × 2 px dot).  Measured on what Chromium drew: each label or readout name
with a combining dot against the same element with its marks taken out; each dot must add at
least 1.5 dark pixels (ink ≥ 50 %) and one of them nearly black.

The symbols with a combining mark are drawn bold in the slider labels (controls.marks_bold) and
the readout's names.
"""
from __future__ import annotations

import io
import time

import numpy as np
import pytest

from .conftest import ARTIFACTS, VoilaServer, write_notebook

pytestmark = pytest.mark.browser

STRIP_JS = r"""(el) => { el.dataset.keep = el.innerHTML;
                         el.innerHTML = el.innerHTML.replace(/[\u0300-\u036f]/g, ''); }"""
BACK_JS = r"""(el) => { el.innerHTML = el.dataset.keep; delete el.dataset.keep; }"""


def _ink(loc) -> np.ndarray:
    from PIL import Image

    return 255 - np.asarray(Image.open(io.BytesIO(loc.screenshot())).convert("L")).astype(int)


def test_every_combining_dot_of_the_slider_crank_shows(browser, tmp_path):
    nb = write_notebook(tmp_path / "dots.ipynb", ["from planargeo.widgets import SliderCrankExplorer",
                                                  "SliderCrankExplorer()"])
    server = VoilaServer(nb, tmp_path / "voila")
    page = browser.new_page(viewport={"width": 1300, "height": 1100})
    try:
        page.goto(server.url + "/", wait_until="domcontentloaded", timeout=180_000)
        ex = page.locator(".planargeo-explorer").first
        ex.locator(".planargeo-readout").first.wait_for(state="attached", timeout=240_000)
        time.sleep(1.0)                                     # the layout settles
        ARTIFACTS.mkdir(exist_ok=True)
        ex.screenshot(path=str(ARTIFACTS / "slider-crank-dots.png"))
        found = []
        for loc in ex.locator(".widget-label, .planargeo-readout td:first-child").all():
            text = loc.text_content()
            dots = text.count("\u0307") + 2 * text.count("\u0308")
            if not dots:
                continue
            loc.scroll_into_view_if_needed()
            a = _ink(loc)
            loc.evaluate(STRIP_JS)
            b = _ink(loc)
            loc.evaluate(BACK_JS)
            h, w = min(a.shape[0], b.shape[0]), min(a.shape[1], b.shape[1])
            d = np.clip(a[:h, :w] - b[:h, :w], 0, 255)
            found.append((text, dots, int((d >= 128).sum()), int(d.max())))
        assert {t for t, *_ in found} >= {"ψ̇₀ (rad/s)", "crank speed ψ̇", "ψ̈ crank"}, found
        faint = [f for f in found if f[2] < 1.5 * f[1] or f[3] < 200]
        assert faint == [], faint
    finally:
        page.close()
        server.stop()
