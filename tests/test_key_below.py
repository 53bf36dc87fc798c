"""A key no corner of the plot has room for: below the axes, outside the plot, in the export too.

The picture says it once (``"below"``: lines of text, each with its colour and its entry's
description, placed in pixels under the plot area); matplotlib draws it as figure texts under
the x tick labels, the page (tests/browser/test_key_below.py) likewise.  The plot, its frame,
ticks and view are those of the picture without the key; the figure grows by the key's height.
"""
from __future__ import annotations

import struct

import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.colors import to_hex

from planargeo.draw import render
from planargeo.draw.picture import Picture
from planargeo.draw.style import COLORS, rc_context
from planargeo.widgets import ImpulseExplorer, SliderCrankExplorer


def _drawn(pic: dict):
    """The matplotlib figure of ``pic``, drawn, with its height in pixels and renderer."""
    with rc_context():
        fig = render.figure(pic)
        FigureCanvasAgg(fig)
        renderer = fig.canvas.get_renderer()
        fig.draw(renderer)
    return fig, fig.get_size_inches()[1] * fig.dpi, renderer


def _down(bb, H):
    """A window extent as (left, top, right, bottom), y down from the figure's top."""
    return bb.x0, H - bb.y1, bb.x1, H - bb.y0


@pytest.mark.parametrize("cls", [ImpulseExplorer, SliderCrankExplorer])
def test_the_export_draws_the_key_below_the_axes(cls, tmp_path):
    ex = cls(display="agg", key=True)
    on = ex.picture()
    assert "below" in on, "this key was meant to find no clear corner"
    ex.set(key=False)
    off = ex.picture()
    fig_on, H_on, r_on = _drawn(on)
    fig_off, H_off, r_off = _drawn(off)
    (ax_on,), (ax_off,) = fig_on.axes, fig_off.axes
    # the axes: the same pixels from the figure's top left, the same view and ticks
    assert _down(ax_on.get_window_extent(r_on), H_on) == pytest.approx(_down(ax_off.get_window_extent(r_off), H_off))
    assert ax_on.get_xlim() == ax_off.get_xlim() and ax_on.get_ylim() == ax_off.get_ylim()
    assert list(ax_on.get_xticks()) == list(ax_off.get_xticks())
    assert list(ax_on.get_yticks()) == list(ax_off.get_yticks())
    # the key's lines: figure texts, in order, in their colours, under the axes and their x tick
    # labels, inside the figure, at least 11 px
    texts = [t for t in fig_on.texts if (t.get_gid() or "").endswith(":below")]
    assert [t.get_text() for t in texts] == [b["text"] for b in on["below"]]
    assert [to_hex(t.get_color()) for t in texts] == [to_hex(b["color"]) for b in on["below"]]
    assert not [a for a in ax_on.get_children() if (getattr(a, "get_gid", lambda: None)() or "").startswith("key ")]
    axes_bottom = _down(ax_on.get_window_extent(r_on), H_on)[3]
    labels = [_down(t.get_window_extent(r_on), H_on) for t in ax_on.get_xticklabels()
              if t.get_text() and ax_on.axison]
    under = max([axes_bottom] + [b[3] for b in labels])
    tops = []
    for t in texts:
        left, top, right, bottom = _down(t.get_window_extent(r_on), H_on)
        assert top >= under and left >= 0 and right <= on["size"][0] and bottom <= H_on, (t.get_text(), top, under)
        assert t.get_fontsize() * fig_on.dpi / 72.0 >= 11.0
        tops.append(top)
    assert tops == sorted(tops)
    # the PNG export: the figure's pixel size
    ex.set(key=True)
    ex.export_png(tmp_path / "k.png")
    assert struct.unpack(">II", (tmp_path / "k.png").read_bytes()[16:24]) == tuple(on["size"])


def test_a_zoom_with_the_key_below_shows_the_view_asked_for():
    """The page's box is the plot's view (no strip below it to take off)."""
    boxes = {}
    for key in (False, True):
        ex = ImpulseExplorer(display="page", key=key)
        x0, x1, y0, y1 = ex.picture()["box"]
        box = [x0 + 0.1 * (x1 - x0), x1 - 0.2 * (x1 - x0), y0 + 0.15 * (y1 - y0), y1 - 0.15 * (y1 - y0)]
        ok, why = ex.canvas.handle_message({"type": "view", "box": box, "seq": 1})
        assert ok, why
        boxes[key] = ex.picture()["box"]
    assert boxes[True] == boxes[False]


def test_lines_below_grow_the_figure_and_keep_the_plot():
    pic = Picture((-1, 1, -1, 1), size=(300, 260))
    before = pic.to_dict()
    assert "below" not in before
    pic.below("key 1", [], color="#d62728")             # no lines: nothing changes
    assert pic.to_dict() == before
    other = pic.copy()
    pic.below("key 1", [r"$v_{1}$: a velocity pole", "  and its meaning"], color="#d62728", desc="key: v₁")
    pic.below("key 2", ["P: a point"])
    d = pic.to_dict()
    assert d["size"] == [300, 260 + 3 * 14 + 4] and d["margin"][:3] == before["margin"][:3]
    assert d["margin"][3] == before["margin"][3] + 3 * 14 + 4
    assert d["box"] == before["box"] and d["ticks"] == before["ticks"]
    assert [(b["id"], b["text"], b["y"]) for b in d["below"]] == [
        ("key 1", "v₁: a velocity pole", 30.0), ("key 1", "  and its meaning", 44.0), ("key 2", "P: a point", 58.0)]
    assert [b["color"] for b in d["below"]] == ["#d62728", "#d62728", COLORS["text"]]   # the text's by default
    assert [b["desc"] for b in d["below"]] == ["key: v₁", "key: v₁", ""]
    assert "below" not in other.to_dict()              # a copy made before keeps its own lines
