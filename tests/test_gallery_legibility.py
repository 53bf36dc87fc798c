"""Legibility of every gallery figure: text large enough, no label cut off, no two on top of each other.

Each registered figure is built in the gallery's style (every geometric panel drawn
from a picture by :func:`planargeo.draw.render.draw_picture`, charts by matplotlib)
and drawn on Agg.  The texts that are actually drawn (recorded at draw time, so
hidden labels, ticks outside the view and empty texts do not count) must lie
inside the figure, and no two of them may overlap by more than ``TOL`` pixels
in both directions (at the gallery's 100 dpi: 0.7 pt), and every one must be at least
``MIN_TEXT_PX`` (11 px) high at the SVG's natural size in a browser (an SVG's sizes are
in points, shown at 96/72 CSS px per point: ``fontsize × 96 / 72``), the size explorers
are held to too (issue 13).
"""
from __future__ import annotations

import itertools

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import pytest  # noqa: E402
from matplotlib.text import Text  # noqa: E402

from planargeo.gallery.figures import load_all  # noqa: E402
from planargeo.draw.style import LABEL_PT, MIN_TEXT_PX, rc_context  # noqa: E402

TOL = 1.0  # pixels

SPECS = load_all()


def _drawn_texts(fig, monkeypatch):
    """(text, window extent, font size) of every visible non-empty Text drawn while rendering ``fig``.

    Every text of a figure is a matplotlib Text that draws itself (picture labels,
    chart labels, ticks, legends, titles): ``Text.draw`` is observed, each text once.
    """
    drawn, seen = [], set()
    orig = Text.draw

    def note(t, renderer):
        if id(t) not in seen and t.get_visible() and t.get_text():
            seen.add(id(t))
            drawn.append((t.get_text(), t.get_window_extent(renderer), t.get_fontsize()))

    def record(self, renderer):
        orig(self, renderer)
        note(self, renderer)

    monkeypatch.setattr(Text, "draw", record)
    fig.canvas.draw()
    monkeypatch.setattr(Text, "draw", orig)
    return drawn


def _params():
    return [pytest.param(name, id=name) for name in SPECS]


def test_overlap_measure_detects_overlap():
    # the check itself: two texts at the same place overlap, two far apart do not
    from matplotlib.transforms import Bbox

    a, b, c = Bbox([[0, 0], [20, 10]]), Bbox([[5, 2], [25, 12]]), Bbox([[30, 0], [40, 10]])
    assert _overlap(a, b) == (15, 8)
    assert _overlap(a, c)[0] < 0


def _overlap(a, b):
    return (min(a.x1, b.x1) - max(a.x0, b.x0), min(a.y1, b.y1) - max(a.y0, b.y0))


@pytest.mark.parametrize("name", _params())
def test_labels_inside_and_apart(name, monkeypatch):
    with rc_context():
        fig = SPECS[name].build()
        try:
            drawn = _drawn_texts(fig, monkeypatch)
            W, H = fig.bbox.width, fig.bbox.height
            px_per_pt = 96.0 / 72.0          # the SVG shown at its natural size (CSS px per pt)
        finally:
            plt.close(fig)
    assert drawn, f"{name}: no text drawn"
    small = [(t, round(size * px_per_pt, 1)) for t, _, size in drawn if size * px_per_pt < MIN_TEXT_PX]
    assert not small, f"{name}: texts smaller than {MIN_TEXT_PX:g} px at the SVG's natural size: {small}"
    texts = [(t, bb) for t, bb, _ in drawn]
    outside = [(t, [round(v, 1) for v in bb.extents]) for t, bb in texts
               if bb.x0 < -TOL or bb.y0 < -TOL or bb.x1 > W + TOL or bb.y1 > H + TOL]
    assert not outside, f"{name}: texts cut off by the figure edge ({W:g}x{H:g} px): {outside}"
    clashes = []
    for (ta, ba), (tb, bb) in itertools.combinations(texts, 2):
        dx, dy = _overlap(ba, bb)
        if dx > TOL and dy > TOL:
            clashes.append((ta, tb, round(dx, 1), round(dy, 1)))
    assert not clashes, f"{name}: overlapping texts (text, text, dx px, dy px): {clashes}"


def test_the_one_text_size_is_legible():
    """The style's text size is at least MIN_TEXT_PX in a gallery SVG (96 px per inch in a browser)
    and in an explorer's picture (100 dpi at native size)."""
    from planargeo.draw.style import EXPLORER_DPI, RC

    assert RC["savefig.dpi"] == RC["figure.dpi"] == EXPLORER_DPI == 100
    for key in ("font.size", "axes.labelsize", "legend.fontsize", "xtick.labelsize", "ytick.labelsize",
                "axes.titlesize"):
        assert RC[key] >= LABEL_PT and RC[key] * 96 / 72 >= MIN_TEXT_PX - 1e-9, key


@pytest.mark.parametrize("name", _params())
def test_the_explorers_legibility_check_passes(name):
    """The check explorers are held to (planargeo.draw.layout.legibility_problems, at the SVG's natural
    size): text >= 11 px, no overlap, every label inside its axes and the figure."""
    from planargeo.draw.layout import legibility_problems

    with rc_context():
        fig = SPECS[name].build()
        try:
            problems = legibility_problems(fig)
        finally:
            plt.close(fig)
    assert problems == [], f"{name}: {problems}"
