"""Fast frames (widgets/frames.py): blitting shows what a whole draw shows; light PNGs show the frame.

References: Matplotlib's own full draw of the same figure (``canvas.draw``), and the
exact RGBA buffer of the frame for the 256-colour pictures.
"""
from __future__ import annotations

import io
import subprocess
import sys
import textwrap

import numpy as np
import pytest
from ipywidgets import FloatSlider
from PIL import Image

import planargeo.widgets as widgets
from planargeo.widgets.frames import Frames, live_png

#: a 256-colour picture of antialiased line art: channel errors stay below this (of 255)
QUANT_TOL = 64


def _buffer(fig):
    return np.asarray(fig.canvas.buffer_rgba()).astype(int)


def _full_draw(fig):
    fig.canvas.draw()
    return _buffer(fig)


def _drawn_by_artists(name: str) -> None:
    """Skip for a native explorer: it has no figure, its picture is drawn by the page or draw/render."""
    from planargeo.widgets.base import Explorer

    cls = getattr(widgets, name)
    if cls.scene_picture is not Explorer.scene_picture and cls.readout_of is not Explorer.readout_of:
        pytest.skip(f"{name} is native: no figure, no frames")


def _decode(png: bytes) -> np.ndarray:
    return np.asarray(Image.open(io.BytesIO(png)).convert("RGBA")).astype(int)


@pytest.mark.parametrize("name", sorted(widgets.EXPLORERS))
def test_blitted_frame_is_the_whole_draw(name):
    """After a control change, the blitted frame (kept background) equals Matplotlib's full draw.

    The only allowed differences are the few pixels where content crosses the axes'
    frame (drawn under the content when blitting, above low-zorder content in a full draw).
    """
    _drawn_by_artists(name)
    ex = getattr(widgets, name)(display="agg")
    slider = next(k for k, w in ex.controls.items() if isinstance(w, FloatSlider)
                  and w.value + w.step <= w.max)
    ex.frames.draw()
    full_before = ex.frames.n_full
    ex.controls[slider].value = ex.controls[slider].value + ex.controls[slider].step
    assert ex.message == "", ex.message
    blitted = _buffer(ex.fig).copy()
    drawn = _full_draw(ex.fig)
    d = np.abs(blitted - drawn).max(axis=-1)
    assert (d > QUANT_TOL).mean() < 2e-5, (name, int((d > QUANT_TOL).sum()))
    assert (d > 0).mean() < 5e-3, (name, int((d > 0).sum()))
    if ex.frames.n_full == full_before:        # the view stayed: the frame was blitted
        assert ex.frames.n_blit >= 1


def test_view_change_draws_the_whole_figure():
    _drawn_by_artists("ProjectiveExplorer")
    ex = widgets.ProjectiveExplorer(display="agg")
    ex.frames.draw()
    n_full, n_blit = ex.frames.n_full, ex.frames.n_blit
    ex.frames.draw()
    assert (ex.frames.n_full, ex.frames.n_blit) == (n_full, n_blit + 1)
    x0, x1 = ex.ax.get_xlim()
    ex.ax.set_xlim(x0 - 1.0, x1 + 1.0)         # new ticks: the background must be drawn again
    ex.frames.draw()
    assert ex.frames.n_full == n_full + 1
    np.testing.assert_array_equal(_buffer(ex.fig), _full_draw(ex.fig))
    ex.frames.invalidate()                      # a change the key cannot see: drawn whole on request
    ex.frames.draw()
    assert ex.frames.n_full == n_full + 2


def test_figure_texts_are_content():
    """A figure-level text that changes every frame (the chain's clock) is redrawn by blitting."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(3, 2), dpi=60)
    FigureCanvasAgg(fig)
    ax = fig.add_subplot()
    ax.plot([0, 1], [0, 1])
    clock = fig.text(0.1, 0.05, "t = 0.00 s")
    frames = Frames(fig)
    frames.draw()
    clock.set_text("t = 1.25 s")
    frames.draw()
    assert frames.n_blit == 1
    np.testing.assert_array_equal(_buffer(fig), _full_draw(fig))


def _frame_pair():
    _drawn_by_artists("ChainExplorer")
    ex = widgets.ChainExplorer(links=6, display="agg", **{"velocity poles": True, "internal forces": True})
    ex.frames.draw()
    before = np.asarray(ex.fig.canvas.buffer_rgba()).copy()
    h = [h for h in ex.handles() if h.where() is not None][-1]
    x, y = h.where()
    ex.drag(h.name, (x, y), (x + 0.05, y), steps=1)
    after = np.asarray(ex.fig.canvas.buffer_rgba()).copy()
    return before, after


def test_live_png_is_the_frame():
    before, after = _frame_pair()
    pic = _decode(live_png(after))
    assert pic.shape == after.shape and (pic[..., 3] == 255).all()
    err = np.abs(pic[..., :3] - after[..., :3].astype(int)).max(axis=-1)
    assert err.max() <= QUANT_TOL and err.mean() < 2.0
    white = (after[..., :3] == 255).all(axis=-1)
    assert white.mean() > 0.5 and (pic[white][:, :3] == 255).all()   # the background stays pure white
    assert len(Image.open(io.BytesIO(live_png(after))).getpalette()) <= 768


def test_live_png_diff_draws_only_what_changed():
    """A diff picture over the previous picture gives the new frame; unchanged pixels are transparent."""
    before, after = _frame_pair()
    changed = (before.view(np.uint32) != after.view(np.uint32)).squeeze(-1)
    assert 0 < changed.mean() < 0.5
    prev = _decode(live_png(before))
    diff = _decode(live_png(after, changed))
    assert (diff[~changed][:, 3] == 0).all() and (diff[changed][:, 3] == 255).all()
    shown = np.where(diff[..., 3:4] > 0, diff, prev)[..., :3]
    assert np.abs(shown - after[..., :3].astype(int)).max() <= QUANT_TOL
    nothing = _decode(live_png(after, np.zeros_like(changed)))
    assert (nothing[..., 3] == 0).all()


def test_ipympl_frames_are_sent_at_once_as_diffs():
    """Under ipympl an update sends its picture right away (no round trip): full first, then diffs."""
    _drawn_by_artists("ChainExplorer")
    code = textwrap.dedent("""
        import io, json
        import numpy as np
        import matplotlib
        matplotlib.use("module://ipympl.backend_nbagg")
        from PIL import Image
        from planargeo.widgets import ChainExplorer
        ex = ChainExplorer(links=4)
        assert ex.display_mode == "ipympl"
        sent = []
        ex.fig.canvas.send = lambda content, buffers=None: sent.append((content, buffers))
        exact = [np.asarray(ex.fig.canvas.buffer_rgba()).astype(int)]
        for v in (-28.0, -26.0):
            n = len(sent)
            ex.controls["angle"].value = v
            binaries = [b[0] for c, b in sent[n:] if b and json.loads(c["data"])["type"] == "binary"]
            assert len(binaries) == 1, len(binaries)       # one picture per update, sent at once
            pic = np.asarray(Image.open(io.BytesIO(bytes(binaries[0]))).convert("RGBA")).astype(int)
            exact.append(np.asarray(ex.fig.canvas.buffer_rgba()).astype(int))
            alpha = pic[..., 3]
            changed = (exact[-1] != exact[-2]).any(axis=-1)
            assert changed.any() and (alpha[changed] == 255).all() and (alpha[~changed] == 0).all()
            assert np.abs(pic[changed][:, :3] - exact[-1][changed][:, :3]).max() <= 64
        print("ok")
    """)
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert r.returncode == 0 and r.stdout.strip().endswith("ok"), r.stderr[-2000:]
