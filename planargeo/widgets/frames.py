"""Drawing an explorer's figure frame after frame, and sending it to the page quickly.

An explorer redraws its figure on every slider step, mouse move and Play frame.
Three things make a frame cheap:

* **Blitting** (:class:`Frames`): the axes' frame, ticks, tick labels and grid do
  not change while the view stays put (during a drag, a Play, most slider
  steps), so they are drawn once, kept as a pixel copy, and each frame restores
  that copy and draws only the content (every artist added to the axes or the
  figure) over it.  Any change of the view, the figure size or the axes'
  decorations is noticed (:func:`background_key`) and draws the whole figure.
* **A light picture for the page** (:func:`live_png`): the live view is sent as
  a 256-colour PNG, a third of the bytes and half the encoding time of a
  full-colour one, for a figure of flat-coloured lines and text that looks the
  same.  Exports (SVG, PNG, GIF, MP4) and the notebook's stored picture are
  drawn at full colour, by Matplotlib.
* **No round trip under ipympl** (:func:`live_canvas`): ipympl's ``draw_idle``
  asks the page to ask the kernel for a draw; an explorer draws its frame at
  once and sends it (:meth:`LiveCanvas.blit`), and its PNGs are the light ones.

Examples
--------
>>> from matplotlib.figure import Figure
>>> from matplotlib.backends.backend_agg import FigureCanvasAgg
>>> fig = Figure(figsize=(2, 2), dpi=50); _ = FigureCanvasAgg(fig)
>>> ax = fig.add_subplot(); line, = ax.plot([0, 1], [0, 1])
>>> frames = Frames(fig)
>>> frames.draw(); frames.n_full, frames.n_blit
(1, 0)
>>> line.set_ydata([1, 0]); frames.draw(); frames.n_full, frames.n_blit
(1, 1)
>>> _ = ax.set_xlim(0, 2); frames.draw(); frames.n_full, frames.n_blit
(2, 1)
>>> png = live_png(np.asarray(fig.canvas.buffer_rgba()))
>>> png[:8] == b"\\x89PNG\\r\\n\\x1a\\n"
True
"""
from __future__ import annotations

import base64
import functools
import io

import numpy as np
from matplotlib.axis import Axis
from matplotlib.spines import Spine

__all__ = ["Frames", "background_key", "live_png", "live_canvas"]


def _titles(ax) -> list:
    return [t for t in (ax.title, getattr(ax, "_left_title", None), getattr(ax, "_right_title", None))
            if t is not None]


def _decoration(ax, a) -> bool:
    """True for what belongs to an axes' background: patch, spines, axes, titles."""
    return a is ax.patch or isinstance(a, (Spine, Axis)) or any(a is t for t in _titles(ax))


def content(fig) -> list:
    """Everything drawn over the background, in drawing order: each axes' own artists, then the figure's.

    Parameters
    ----------
    fig : matplotlib.figure.Figure

    Returns
    -------
    list of (matplotlib.axes.Axes or None, list of matplotlib.artist.Artist)
        Per axes (in the figure's drawing order), its content sorted by zorder;
        last ``(None, [...])``: the figure's own artists (texts, lines, legends).
    """
    out = []
    for ax in sorted(fig.axes, key=lambda a: a.get_zorder()):
        arts = [a for a in ax.get_children() if not _decoration(ax, a)]
        out.append((ax, sorted(arts, key=lambda a: a.get_zorder())))
    own = [a for a in fig.get_children() if a is not fig.patch and a not in fig.axes]
    out.append((None, sorted(own, key=lambda a: a.get_zorder())))
    return out


def background_key(fig) -> tuple:
    """What the background (figure patch, axes frames, ticks, labels, titles) depends on.

    Two draws with equal keys have the same background pixels.

    Parameters
    ----------
    fig : matplotlib.figure.Figure

    Returns
    -------
    tuple
    """
    key = [tuple(fig.bbox.bounds), float(fig.dpi), tuple(fig.patch.get_facecolor())]
    for ax in fig.axes:
        ax.apply_aspect()
        key += [ax.get_visible(), ax.axison, tuple(np.round(ax.viewLim.bounds, 12)),
                tuple(ax.get_position().bounds), ax.get_xlabel(), ax.get_ylabel(),
                ax.get_xscale(), ax.get_yscale(), tuple(ax.patch.get_facecolor()),
                ax.xaxis.get_visible(), ax.yaxis.get_visible(),
                tuple(ax.get_xticks()), tuple(ax.get_yticks()),
                tuple((t.get_text(), t.get_visible()) for t in _titles(ax))]
    return tuple(key)


class Frames:
    """Draws a figure frame after frame into its Agg buffer, blitting over a kept background.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        A figure with an Agg-based canvas (Agg, ipympl).

    Attributes
    ----------
    n_full, n_blit : int
        Frames drawn whole (the background changed) and by blitting.
    """

    def __init__(self, fig):
        self.fig = fig
        self._background = None
        self._key = None
        self.n_full = 0
        self.n_blit = 0

    def invalidate(self) -> None:
        """Draw the whole figure next time (for a background change :func:`background_key` misses)."""
        self._key = None

    def draw(self) -> None:
        """Draw the current frame into the canvas's buffer (not sent anywhere)."""
        canvas = self.fig.canvas
        key = background_key(self.fig)
        renderer = canvas.get_renderer()
        layers = content(self.fig)
        if key != self._key or self._background is None:
            shown = [a for _, arts in layers for a in arts if a.get_visible()]
            for a in shown:
                a.set_visible(False)
            try:
                renderer.clear()
                self.fig.draw(renderer)
            finally:
                for a in shown:
                    a.set_visible(True)
            self._background = canvas.copy_from_bbox(self.fig.bbox)
            self._key = key
            self.n_full += 1
        else:
            self.n_blit += 1
        canvas.restore_region(self._background)
        for ax, arts in layers:
            for a in arts:
                if a.get_visible():
                    a.draw(renderer)
        self.fig.stale = False


def live_png(rgba, changed=None) -> bytes:
    """A 256-colour PNG of an ``(h, w, 4)`` frame, for the live view in the page.

    Parameters
    ----------
    rgba : numpy.ndarray
        ``uint8`` pixels; the alpha channel is ignored (frames are opaque).
    changed : numpy.ndarray of bool, optional
        ``(h, w)``: only these pixels are sent, the others are transparent (an
        ipympl "diff" frame, drawn over the previous one).

    Returns
    -------
    bytes
        PNG data: palette of at most 255 colours (pure white kept exact) plus,
        with ``changed``, one transparent entry.
    """
    from PIL import Image

    rgb = np.ascontiguousarray(np.asarray(rgba)[..., :3])
    h, w = rgb.shape[:2]
    if changed is None:
        q = Image.fromarray(rgb).quantize(255, method=Image.Quantize.FASTOCTREE,
                                          dither=Image.Dither.NONE)
        idx = None
    else:  # only the changed pixels (a few per cent during a drag) are quantised
        idx = np.full((h, w), 255, dtype=np.uint8)
        sel = rgb[changed]
        q = Image.fromarray(sel[None] if len(sel) else np.zeros((1, 1, 3), np.uint8)).quantize(
            255, method=Image.Quantize.FASTOCTREE, dither=Image.Dither.NONE)
        if len(sel):
            idx[changed] = np.asarray(q)[0]
    used = np.array(q.getpalette()[:765], dtype=np.int64).reshape(-1, 3)
    pal = np.zeros((256, 3), dtype=np.int64)
    pal[:len(used)] = used
    pal[np.all(pal >= 250, axis=1)] = 255    # the background stays pure white
    kw = {}
    if idx is not None:
        q = Image.frombytes("P", (w, h), idx.tobytes())
        pal[255] = 0
        kw["transparency"] = 255
    q.putpalette(pal.astype(np.uint8).ravel().tolist())
    buf = io.BytesIO()
    q.save(buf, format="png", compress_level=1, **kw)
    return buf.getvalue()


def live_canvas(fig):
    """Attach an ipympl canvas to ``fig`` that sends light PNGs, and return it.

    The figure gets its own figure manager (toolbar included) without pyplot's
    bookkeeping: it is not a pyplot figure (``plt.gcf`` does not see it) and
    redraws only when its explorer says so.

    Parameters
    ----------
    fig : matplotlib.figure.Figure

    Returns
    -------
    ipympl.backend_nbagg.Canvas
    """
    from ipympl.backend_nbagg import FigureManager

    canvas = _live_canvas_class()(fig)
    FigureManager(canvas, 1)
    return canvas


@functools.lru_cache(maxsize=None)
def _live_canvas_class():
    """ipympl's canvas whose frames are :func:`live_png` pictures (made on first use: ipympl is
    imported only where it is the front end)."""
    from ipympl.backend_nbagg import Canvas

    class LiveCanvas(Canvas):
        """ipympl's canvas, whose frames are :func:`live_png` pictures."""

        def get_diff_image(self):
            if not self._png_is_old:
                return None
            pixels = np.asarray(self.get_renderer().buffer_rgba())
            buff = pixels.view(np.uint32).squeeze(2)
            if self._force_full or buff.shape != self._last_buff.shape:
                self.set_image_mode("full")
                changed = None
            else:
                self.set_image_mode("diff")
                changed = buff != self._last_buff
            self._last_buff = buff.copy()
            self._force_full = False
            self._png_is_old = False
            return live_png(pixels, changed)

        def send_binary(self, data):
            # before the page's view exists the picture travels as the model's data URL:
            # the whole frame, as a complete data URL (ipympl's own omits the prefix)
            if self.syncing_data_url:
                rgba = self._last_buff.view(np.uint8).reshape((*self._last_buff.shape, 4))
                self._data_url = "data:image/png;base64," + base64.b64encode(live_png(rgba)).decode("ascii")
            self.send({"data": '{"type": "binary"}'}, buffers=[data])

    return LiveCanvas
