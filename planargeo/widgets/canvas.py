"""The page renderer's widget: a picture drawn by the browser, handles dragged in the page.

:class:`PictureCanvas` is an `anywidget <https://anywidget.dev>`_ whose ES module
(``canvas.js``, shipped beside this file: no build step, no network) draws a
picture's plain data (:mod:`planargeo.draw.picture`) as SVG.  The page moves a
dragged handle, zooms and pans at once, and sends the kernel one request at a time.

Kernel → page
-------------
Setting :attr:`PictureCanvas.picture` (the complete plain dict of
:meth:`planargeo.draw.picture.Picture.to_dict`, kept whole in Python) sends the page
only what changed since the version it holds, as an *update*::

    {"version": n, "base": n - 1,            # applies to version n - 1 only
     "head": {...},                          # view, size, ticks, title, lines below (when changed)
     "order": [id, ...],                     # drawing order (when it changed)
     "set": {id: {field: value, ...}},       # changed fields of new or changed elements
     "handles": [[id, x, y], ...],           # when they moved
     "tips": {handle id: text}}              # when they changed

Coordinates are rounded to a tenth of a pixel of the picture's view (:func:`wire_digits`),
parts are short arrays (:func:`wire_element`) and descriptions stay in the kernel:
an element is marked described, and the page asks for its text when the pointer
rests on it.  An update made while a request is answered travels in the request's
``ack``; any other (a slider, Play driven by the kernel) is sent alone as
``{"type": "update", ...}``.  A view that opens (a page reload, a second display)
starts from the synced ``snapshot`` (the whole current picture, wire format) and
asks for the whole picture again whenever an update does not apply to its version.
An export button's file goes as ``{"type": "download", "name", "mime", "data" (base64),
"client"}`` (:meth:`PictureCanvas.download`): the view that last sent a request (or any
view, ``client`` None) saves it at once through a Blob and a temporary link.

In the page
-----------
The figure is shown at its container's width when that is narrower than the picture
(aspect kept); its text is drawn larger as it shrinks so that it is never shown below
11 px, but at most 1.15 times larger (the labels were placed for their own size): with
the labels' 11.46 px, down to 0.835 of the figure's size.  Narrower, the figure keeps that
size and its container scrolls sideways.  Pointer positions are
read in the shown scale.  The element hovered or clicked is the nearest to the pointer
within 6 px (ties within a pixel: the one drawn last); a click focuses it (the rest
faded), a click on the background or the element leaving the picture ends the focus.
The figure takes the keyboard's focus (Tab; a visible outline): Tab and Shift-Tab mark
each handle in turn, the arrow keys nudge the marked one (Shift: 10 times as far).

Page → kernel
-------------
At most one request is in flight; while one is, the page keeps only the latest
request of each type (in the order they were last asked) and sends them one by one as
the ``ack`` arrives.  Every request carries
``"seq"`` (an int) and the page's ``"client"`` id (echoed in the ack):

``{"type": "drag", "id": str, "x": float, "y": float}``
    a handle moved to ``(x, y)`` (data coordinates);
``{"type": "release", "id": str}``
    the drag of a handle ended (the mouse let go, or the last arrow key that nudged it:
    each press of an arrow key is a ``drag`` of the handle last clicked), after its last ``drag``;
``{"type": "view", "box": [x0, x1, y0, y1] | None}``
    the user zoomed or panned (None: back to the explorer's own view);
``{"type": "tick"}``
    Play: the next frame, please (below);
``{"type": "describe", "id": str}``
    the description of an element (answered in the ack's ``"desc"``);
``{"type": "sync", "version": int | None}``
    the page holds this version; the ack brings the whole picture if it is not the current one;
``{"type": "ping"}``
    nothing to do (the floor of a round trip, for benchmarks).

Every message is checked here before anything acts on it (its type, its fields'
types, finite numbers within :data:`COORD_LIMIT`, a known handle); a bad one is
answered ``ok: false`` and changes nothing.  The kernel answers each request with
``{"type": "ack", "seq", "client", "ok", "message", "ms"[, "update"][, "desc"]}`` (``ms``: the
milliseconds the kernel spent on it, for benchmarks) after the
new picture (if any) is set, so the page knows when it may send the next.

Play
----
While :attr:`PictureCanvas.playing` (a synced Bool, set by the kernel: the explorer's
Play button) is true, the page sends ``{"type": "tick"}`` as soon as the previous reply
has arrived, so the kernel computes the next frame while the page paints this one: the
frames pace themselves to what the kernel and the page manage (one request in flight).
Each checked tick calls ``on_tick()``, which advances the motion by the wall-clock
time since the last tick and sets the new picture (its update travels in the ack).
``on_tick`` raising a :class:`~planargeo.errors.PlanargeoError` refuses the tick: its
message is shown in the page's status line, and the page sends no further tick until
``playing`` is set again.  A tick that arrives after Play stopped does nothing, and
stopping cancels the extra frame below.

The kernel keeps two frames in flight: after answering a tick it calls ``on_tick()``
once more, halfway to the next tick (the interval between the last two ticks, less
the time a frame takes, at least :data:`EXTRA_MIN_S`: a Stop that reached the kernel
while the tick's frame was computed is handled first), and sends that frame alone as an
``update``.  The page
still sends one request at a time; a frame a page cannot paint in time is only a
display frame dropped (each frame covers the wall-clock time since the one before,
so no physics step is skipped).  The page shows at most one new picture per animation
frame: frames that arrive together (the page was busy) wait for the next animation
frame, at most two (beyond that the oldest are drawn at once).  A refusal in such a frame reaches the page as
``{"type": "halt", "message": str}`` (the page shows it and stops ticking).  There
is no extra frame without a running event loop (no kernel: tests, scripts).

Between frames the kernel does Play's work ahead: ``on_idle(seconds)`` is called right
after each frame has gone (a tick's ack, an extra frame), to spend at most about
``seconds`` (:data:`IDLE_SLICE`) on what the next frames will need (the chain
integrates its next chunk of motion), so that no frame waits for a whole chunk.

Examples
--------
>>> seen = []
>>> c = PictureCanvas(on_drag=lambda h, x, y: seen.append((h, x, y)))
>>> c.picture = {"handles": [{"id": "P", "x": 0.0, "y": 0.0}]}
>>> c.handle_message({"type": "drag", "id": "P", "x": 1.0, "y": 2.0, "seq": 1})
(True, '')
>>> c.handle_message({"type": "drag", "id": "Q", "x": 1.0, "y": 2.0, "seq": 2})
(False, "no handle 'Q' in the picture")
>>> c.handle_message({"type": "drag", "id": "P", "x": float("nan"), "y": 2.0, "seq": 3})
(False, 'x must be a finite number, got nan')
>>> seen
[('P', 1.0, 2.0)]

Play: ticks reach ``on_tick`` only while ``playing`` is true; a refusal is a message.

>>> frames = []
>>> def tick():
...     if len(frames) == 2:
...         raise PlanargeoError("the motion ends at t = 2 s")
...     frames.append(len(frames))
>>> p = PictureCanvas(on_tick=tick)
>>> p.handle_message({"type": "tick", "seq": 1})      # not playing: nothing happens
(True, '')
>>> p.playing = True
>>> [p.handle_message({"type": "tick", "seq": k}) for k in (2, 3, 4)]
[(True, ''), (True, ''), (False, 'the motion ends at t = 2 s')]
>>> frames
[0, 1]

Updates carry what changed: a moved point sends its parts, not its colour.

>>> from planargeo.draw.picture import Picture
>>> def picture(x):
...     pic = Picture((-2, 2, -2, 2), size=(200, 200))
...     pic.point("P", [0.0, -x, 1.0], role="twist", symbol="P", desc=f"a pole at x = {x}")
...     pic.line("l", [1.0, 0.0, -1.0], role="wrench", symbol="l")     # clear of P (its label stays)
...     return pic.to_dict()
>>> c = PictureCanvas()
>>> c.picture = picture(0.5)
>>> first = c.last_update
>>> sorted(first["set"]), first["order"], first["base"]
(['P', 'l'], ['l', 'P'], 0)
>>> c.picture = picture(1.0)
>>> u = c.last_update
>>> sorted(u["set"]), sorted(u["set"]["P"]), "head" in u, u["version"]
(['P'], ['parts'], False, 2)
>>> c.describe("P")
'P — a pole at x = 1.0'
"""
from __future__ import annotations

import asyncio
import base64
import contextlib
import math
import numbers
import time
from pathlib import Path
from typing import Any, Callable

import anywidget
import numpy as np
import traitlets

from planargeo.errors import InputError, PlanargeoError

__all__ = ["PictureCanvas", "COORD_LIMIT", "wire_digits", "wire_element"]

#: Wall seconds of Play's work ahead done after each frame has gone (``on_idle``).
IDLE_SLICE = 0.006
#: Shortest wait (s) before the extra Play frame: a message that reached the kernel while the
#: tick's frame was computed (the page's Stop) is read, queued and handled first.
EXTRA_MIN_S = 0.005
#: Largest coordinate (in absolute value) a message from the page may carry.
COORD_LIMIT = 1e9
#: Element fields that travel to the page as they are (the rest: parts, described mark).
_STYLE = ("role", "symbol", "color", "width", "dash", "fill", "alpha", "opacity")
_HA = {"left": "l", "center": "c", "right": "r"}
_VA = {"bottom": "b", "center": "c", "top": "t"}
_KINDS = {"text", "mark", "arrow", "glyph", "ellipse"}

#: the page renderer, one ES module shipped in the package (no build step): what it draws with,
#: then the renderer itself
_ESM = "".join(Path(__file__).with_name(name).read_text(encoding="utf-8")
               for name in ("canvas_parts.js", "canvas.js"))
_CSS = """
.pg-canvas { position: relative; font-family: 'DejaVu Sans', sans-serif; user-select: none;
             max-width: 100%; min-width: 0; overflow-x: auto; overflow-y: hidden; }
.pg-canvas svg { display: block; touch-action: none; outline: none; height: auto; }
.pg-canvas svg:focus-visible:not(.pg-pointer) { outline: 2px solid #1a73e8; outline-offset: -2px; }
.pg-canvas svg text { font-size: var(--pg-font); }
.pg-canvas svg text.pg-title { font-size: calc(var(--pg-font) + 1px); }
.pg-bar { display: flex; gap: 8px; align-items: center; height: 24px; font-size: 12px; max-width: 100%;
          position: sticky; left: 0; }
.pg-bar button { font-size: 12px; padding: 1px 8px; flex: 0 0 auto; white-space: nowrap; }
.pg-status { color: #b00020; white-space: nowrap; overflow: hidden; text-overflow: ellipsis;
             min-width: 0; flex: 1 1 auto; }
.pg-bg { fill: white; }
.pg-frame { fill: none; stroke: #444; stroke-width: 1; pointer-events: none; }
.pg-axes line { stroke: #444; stroke-width: 1; }
.pg-axes text, .pg-title { fill: #222; }
.pg-el.pg-faded { opacity: 0.18; }
.pg-el.pg-hover path, .pg-el.pg-hover line { stroke-width: 3; }
.pg-handle { fill: rgba(0, 0, 0, 0); stroke: rgba(0, 0, 0, 0.35); stroke-width: 1; cursor: grab; }
.pg-handle:hover, .pg-handle.pg-dragging { stroke: #000; stroke-width: 1.6; fill: rgba(255, 255, 0, 0.25); }
.pg-canvas svg:focus .pg-handle.pg-kbd { stroke: #1a73e8; stroke-width: 2.5; fill: rgba(26, 115, 232, 0.2); }
.pg-tip { position: absolute; max-width: 210px; background: #fffff0; border: 1px solid #888;
          padding: 3px 6px; font-size: 12px; pointer-events: none; z-index: 2; }
"""


def _finite(name: str, v) -> float:
    if isinstance(v, bool) or not isinstance(v, numbers.Real) or not math.isfinite(float(v)):
        raise PlanargeoError(f"{name} must be a finite number, got {v!r}")
    v = float(v)
    if abs(v) > COORD_LIMIT:
        raise PlanargeoError(f"{name} must be within ±{COORD_LIMIT:g}, got {v:g}")
    return v


def wire_digits(head: dict) -> int:
    """Decimals of a data coordinate that the page needs: a tenth of a pixel of the view.

    Parameters
    ----------
    head : dict
        A picture's ``size``, ``margin`` and ``box``.

    Returns
    -------
    int

    Examples
    --------
    >>> wire_digits({"size": [560, 540], "margin": [6, 6, 6, 30], "box": [-5, 5, -5, 5]})
    3
    """
    try:
        (w, h), (ml, mr, mt, mb), (x0, x1, y0, y1) = head["size"], head["margin"], head["box"]
        k = max((w - ml - mr) / (x1 - x0), (h - mt - mb) / (y1 - y0))
        return max(0, min(12, math.ceil(math.log10(10.0 * k))))
    except (KeyError, TypeError, ValueError, ZeroDivisionError):
        return 6


def wire_element(el: dict, nd: int) -> dict:
    """One element of a picture as the page receives it: short parts, no description text.

    Parts become arrays (``["P", closed, x0, y0, x1, y1, ...]`` a path,
    ``["E", x, y, a, b, c, d]`` an ellipse, ``["M", x, y, shape, px]`` a marker,
    ``["G", x, y, r, ccw]`` a glyph, ``["A", x, y, dx, dy]`` an arrow,
    ``["T", x, y, dx, dy, text, "lb"]`` a label with its alignment), data coordinates
    rounded to ``nd`` decimals and pixel offsets to a tenth; hidden labels are left
    out; ``"d": 1`` marks an element whose description the page may ask for.

    Parameters
    ----------
    el : dict
        An element of :meth:`planargeo.draw.picture.Picture.to_dict`.
    nd : int
        Decimals of a data coordinate (:func:`wire_digits`).

    Returns
    -------
    dict

    Examples
    --------
    >>> wire_element({"id": "P", "role": "twist", "symbol": "P", "desc": "a pole", "color": "#1f77b4",
    ...               "parts": [{"p": "mark", "x": 0.123456, "y": 1.0, "shape": "o", "size": 6.94}]}, 3)
    {'role': 'twist', 'symbol': 'P', 'color': '#1f77b4', 'd': 1, 'parts': [['M', 0.123, 1.0, 'o', 6.9]]}
    """
    out = {k: el[k] for k in _STYLE if k in el}
    if el.get("desc") or el.get("symbol"):
        out["d"] = 1
    rnd = round
    parts = []
    add = parts.append
    x0 = y0 = rx = ry = None     # the last point rounded (a pole's marker, glyph and label share it)
    for p in el.get("parts", ()):
        k = p.get("p")
        if k == "path":
            xy = p["xy"]
            head = ["P", 1 if p.get("closed") else 0]
            if len(xy) > 3:        # rounded together (numpy: a long path costs microseconds)
                add(head + (np.round(np.asarray(xy, dtype=float).ravel(), nd) + 0.0).tolist())
            else:
                for x, y in xy:
                    head += (rnd(x, nd), rnd(y, nd))
                add(head)
            continue
        if k not in _KINDS or k == "text" and p.get("hidden"):
            continue
        x, y = p["x"], p["y"]
        if x is not x0 or y is not y0:
            x0, y0, rx, ry = x, y, rnd(x, nd), rnd(y, nd)
        if k == "text":
            add(["T", rx, ry, rnd(p.get("dx", 0.0), 1), rnd(p.get("dy", 0.0), 1), p.get("text", ""),
                 _HA.get(p.get("ha"), "l") + _VA.get(p.get("va"), "b")])
        elif k == "mark":
            add(["M", rx, ry, p.get("shape", "o"), rnd(p.get("size", 6.0), 1)])
        elif k == "arrow":
            add(["A", rx, ry, rnd(p.get("dx", 0.0), 1), rnd(p.get("dy", 0.0), 1)])
        elif k == "glyph":
            add(["G", rx, ry, rnd(p.get("r", 8.0), 1), 1 if p.get("ccw") else 0])
        elif k == "ellipse":
            add(["E", rx, ry, *(rnd(v, nd + 1) for v in p["m"])])
    out["parts"] = parts
    return out


class PictureCanvas(anywidget.AnyWidget):
    """A picture drawn in the page (module docstring).

    Parameters
    ----------
    on_drag : callable ``(handle id, x, y) -> None``, optional
        Called for a checked drag request; raise a :class:`~planargeo.errors.PlanargeoError`
        to refuse the position (the page snaps the handle back and shows the reason).
    on_view : callable ``(box or None) -> None``, optional
        Called for a checked zoom / pan / reset request.
    on_release : callable ``(handle id) -> None``, optional
        Called when the page's drag of a handle has ended.
    on_tick : callable ``() -> None``, optional
        Called for each checked Play tick while :attr:`playing` is true; it advances the
        motion and sets the new picture, or raises a
        :class:`~planargeo.errors.PlanargeoError` to refuse (the message is shown).
    on_idle : callable ``(seconds) -> bool``, optional
        Play's work ahead, called after each frame has gone with the wall seconds it may
        spend; True when work is left.  Whatever it raises is dropped (the frame that
        needs the work reports it).
    around : callable ``() -> context manager``, optional
        Wraps the handling of each request *and its reply*: e.g. other widgets' syncs
        held until the reply (with the new picture) has gone, so that the page paints
        the picture before it works on them.
    said : callable ``(message) -> bool``, optional
        Whether a refusal's message is already shown beside the canvas (an explorer's message
        line and picture): then the page does not repeat it beside "reset view".
    **kwargs
        Passed to :class:`anywidget.AnyWidget`.

    Attributes
    ----------
    picture : dict
        The picture's data (:meth:`planargeo.draw.picture.Picture.to_dict`), whole;
        setting it sends the page what changed.
    playing : bool
        Play is on: the page asks for frames (synced; set by the kernel).
    snapshot
        The whole current picture in the page's format (synced: read by a view when it
        opens; never sent on its own).
    defer : bool
        Answer each request after the kernel's message handler has returned (class
        attribute, default True; without a running event loop requests are answered at once).
    n_requests : int
        Requests answered so far.
    version : int
        Updates made so far (the version of the picture the page should hold).
    last_update : dict or None
        The last update made (for tests and benchmarks).
    """

    #: Answer a request after the kernel's message handler has returned (when an event
    #: loop runs): the kernel publishes "idle" as its handler returns, so its busy/idle
    #: pair reaches the page while the request is worked on, before the reply.  JupyterLab
    #: works on every busy/idle change (the favicon, the toolbar's kernel status, a forced
    #: layout: about 10 ms of the page's main thread per pair, page_trace.py); after the
    #: reply it would delay the new picture's paint.
    defer = True

    _esm = _ESM
    _css = _CSS
    picture = traitlets.Dict()
    playing = traitlets.Bool(False).tag(sync=True)
    snapshot = traitlets.Any(None).tag(sync=True, to_json=lambda _v, w: w._snapshot())

    def __init__(self, on_drag: Callable[[str, float, float], Any] | None = None,
                 on_view: Callable[[Any], Any] | None = None,
                 on_tick: Callable[[], Any] | None = None,
                 around: Callable[[], Any] | None = None,
                 on_idle: Callable[[float], Any] | None = None,
                 on_release: Callable[[str], Any] | None = None,
                 said: Callable[[str], bool] | None = None, **kwargs):
        # what the page holds (set before the widget opens: opening reads the snapshot)
        self.version = 0
        self.last_update = None
        self._sent: dict[str, dict] = {}
        self._src: dict[str, dict] = {}
        self._order: list[str] = []
        self._head: dict = {}
        self._head_src: dict = {}
        self._handles: list = []
        self._tips: dict = {}
        self._dirty = False
        self._in_request = False
        self._extra = None                 # the pending extra Play frame (an event loop's handle)
        self._last_client = None           # the view that sent the last request (downloads go there)
        self._tick_at = None               # when the last tick arrived (perf_counter)
        self._tick_gap = None              # seconds between the last two ticks
        self._tick_cost = 0.0              # seconds the last tick's frame took
        self.n_extra_frames = 0
        super().__init__(**kwargs)
        self.on_drag = on_drag
        self.on_view = on_view
        self.on_tick = on_tick
        self.on_idle = on_idle
        self.on_release = on_release
        self.said = said
        self.around = around or contextlib.nullcontext
        # never wider than its container (ipywidgets' layout owns the box's inline style): a
        # figure too wide to shrink scrolls inside the widget instead of being cut off
        if self.layout.max_width is None:
            self.layout.max_width = "100%"
        if self.layout.min_width is None:
            self.layout.min_width = "0"
        self.n_requests = 0
        self.on_msg(self._on_msg)

    @traitlets.observe("playing")
    def _playing_set(self, change) -> None:
        if not change["new"]:          # Play stopped: no frame after it
            self._cancel_extra()

    # ------------------------------------------------------------------ kernel → page
    @traitlets.observe("picture")
    def _picture_set(self, _change) -> None:
        self._dirty = True
        if not self._in_request:       # inside a request the update travels in its ack
            update = self._flush()
            if update is not None:
                self.send({"type": "update", **update})

    def _flush(self) -> dict | None:
        """The update from what the page holds to :attr:`picture` (None: nothing changed)."""
        if not self._dirty:
            return None
        self._dirty = False
        pic = self.picture
        update: dict[str, Any] = {}
        head = {k: pic[k] for k in ("size", "margin", "box", "title", "ticks", "font_px", "below") if k in pic}
        if head != self._head_src:
            self._head_src = head
            self._head = {**head, "nd": wire_digits(head)}
            update["head"] = self._head
        nd = self._head.get("nd", 6)
        order, changed, sent = [], {}, self._sent
        new_sent, src, new_src = {}, {} if "head" in update else self._src, {}
        for el in pic.get("elements", ()):
            eid = el.get("id")
            if not isinstance(eid, str) or eid in new_sent:
                continue
            order.append(eid)
            new_src[eid] = el
            if src.get(eid) == el:          # the same data as last time: the same wire element
                new_sent[eid] = sent[eid]
                continue
            w = wire_element(el, nd)
            new_sent[eid] = w
            old = sent.get(eid)
            if old is None:
                changed[eid] = w
                continue
            if w == old:                    # the page holds it already (rounded the same)
                continue
            diff = {k: v for k, v in w.items() if old.get(k) != v}
            if old.keys() != w.keys():
                diff.update({k: None for k in old if k not in w})
            if diff:
                changed[eid] = diff
        self._sent, self._src = new_sent, new_src
        if order != self._order:
            update["order"] = order
            self._order = order
        if changed:
            update["set"] = changed
        handles, tips = [], {}
        for h in pic.get("handles", ()):
            try:
                handles.append([str(h["id"]), round(float(h["x"]), nd), round(float(h["y"]), nd)])
            except (KeyError, TypeError, ValueError):
                continue
            sym, desc = h.get("symbol") or "", h.get("desc") or "drag"
            tips[str(h["id"])] = f"{sym}: {desc}" if sym else desc
        if handles != self._handles:
            update["handles"] = self._handles = handles
        if tips != self._tips:
            update["tips"] = self._tips = tips
        if not update:
            return None
        update["base"] = self.version
        self.version += 1
        update["version"] = self.version
        self.last_update = update
        return update

    def _snapshot(self) -> dict:
        """The whole picture the page should hold now (wire format, the current version)."""
        if getattr(self, "_dirty", False) and not getattr(self, "_in_request", False):
            self._flush()
        return {"version": getattr(self, "version", 0), "base": None, "head": getattr(self, "_head", {}),
                "order": list(getattr(self, "_order", [])), "set": dict(getattr(self, "_sent", {})),
                "handles": getattr(self, "_handles", []), "tips": getattr(self, "_tips", {})}

    def download(self, name: str, mime: str, data: bytes) -> dict:
        """Make the page download ``data`` as the file ``name`` (one click on an export button).

        The bytes travel in a message (base64); the view the page last used saves them through a
        Blob and a temporary link (no server, works offline).  Only that view downloads (a
        second display of the widget does not save the file twice).

        Parameters
        ----------
        name : str
            The file's name (no folders).
        mime : str
            Its media type, e.g. ``"image/svg+xml"``.
        data : bytes
            Its contents.

        Returns
        -------
        dict
            The message sent.

        Raises
        ------
        InputError
            A name with a folder in it, or data that is not bytes.

        Examples
        --------
        >>> c = PictureCanvas()
        >>> m = c.download("a.svg", "image/svg+xml", b"<svg/>")
        >>> m["type"], m["name"], m["data"]
        ('download', 'a.svg', 'PHN2Zy8+')
        """
        if not isinstance(name, str) or not name or "/" in name or "\\" in name:
            raise InputError(f"name must be a file name without folders, got {name!r}")
        if not isinstance(data, (bytes, bytearray)):
            raise InputError(f"data must be bytes, got {type(data).__name__}")
        msg = {"type": "download", "name": name, "mime": str(mime),
               "data": base64.b64encode(bytes(data)).decode("ascii"), "client": self._last_client}
        self.send(msg)
        return msg

    def describe(self, eid: str) -> str:
        """The hover text of the element ``eid``: its symbol and description.

        Parameters
        ----------
        eid : str
            The element's id.

        Returns
        -------
        str

        Raises
        ------
        PlanargeoError
            No such element in the picture.
        """
        for el in self.picture.get("elements", ()):
            if el.get("id") == eid:
                sym, desc = el.get("symbol") or "", el.get("desc") or ""
                return f"{sym} — {desc}" if sym and desc else sym or desc
        raise PlanargeoError(f"no element {eid!r} in the picture")

    # ------------------------------------------------------------------ page → kernel
    def handle_message(self, msg) -> tuple[bool, str]:
        """Check one message from the page and act on it.

        Parameters
        ----------
        msg : dict
            The message (module docstring).

        Returns
        -------
        (bool, str)
            Whether it was taken, and the reason when it was not.

        Raises
        ------
        Exception
            Whatever ``on_drag``, ``on_view`` or ``on_tick`` raise other than a
            :class:`~planargeo.errors.PlanargeoError` (a refusal); the widget answers
            such a request as not taken, and the exception goes no further.
        """
        ok, why, _extra = self._handle(msg)
        return ok, why

    def _handle(self, msg) -> tuple[bool, str, dict]:
        try:
            if not isinstance(msg, dict):
                raise PlanargeoError(f"a message must be a dict, got {type(msg).__name__}")
            kind = msg.get("type")
            if kind == "ping":
                return True, "", {}
            if kind in ("drag", "release"):
                hid = msg.get("id")
                if not isinstance(hid, str) or hid not in {h.get("id") for h in
                                                           self.picture.get("handles", [])}:
                    raise PlanargeoError(f"no handle {hid!r} in the picture")
                if kind == "release":
                    if self.on_release is not None:
                        self.on_release(hid)
                    return True, "", {}
                x, y = _finite("x", msg.get("x")), _finite("y", msg.get("y"))
                if self.on_drag is not None:
                    self.on_drag(hid, x, y)
                return True, "", {}
            if kind == "tick":
                if self.playing and self.on_tick is not None:
                    self._cancel_extra()
                    now = time.perf_counter()
                    if self._tick_at is not None:
                        self._tick_gap = now - self._tick_at
                    self._tick_at = now
                    self.on_tick()
                    self._tick_cost = time.perf_counter() - now
                    return True, "", {"extra": True}
                return True, "", {}
            if kind == "view":
                box = msg.get("box")
                if box is not None:
                    if not isinstance(box, (list, tuple)) or len(box) != 4:
                        raise PlanargeoError(f"box must be [x0, x1, y0, y1], got {box!r}")
                    box = [_finite(f"box[{k}]", v) for k, v in enumerate(box)]
                    if not (box[1] > box[0] and box[3] > box[2]):
                        raise PlanargeoError(f"box must have x0 < x1 and y0 < y1, got {box}")
                if self.on_view is not None:
                    self.on_view(box)
                return True, "", {}
            if kind == "describe":
                eid = msg.get("id")
                if not isinstance(eid, str):
                    raise PlanargeoError(f"id must be an element's id, got {eid!r}")
                return True, "", {"desc": self.describe(eid), "id": eid}
            if kind == "sync":
                v = msg.get("version")
                if v is not None and (isinstance(v, bool) or not isinstance(v, int)):
                    raise PlanargeoError(f"version must be an int or None, got {v!r}")
                return True, "", {"sync": v}
            raise PlanargeoError(f"unknown message type {kind!r}")
        except PlanargeoError as exc:
            return False, str(exc), {}

    def _on_msg(self, _widget, content, _buffers) -> None:
        loop = None
        if self.defer:
            with contextlib.suppress(RuntimeError):
                loop = asyncio.get_running_loop()
        if loop is None:       # no event loop (no kernel: tests, scripts): answered at once
            self._answer_around(content)
        else:                  # after the kernel has said it is idle again (class docstring, defer)
            loop.call_soon(self._answer_around, content)

    def _answer_around(self, content) -> None:
        with self.around():      # the reply leaves before what the wrapper held
            self._answer(content)

    def _answer(self, content) -> None:
        t0 = time.perf_counter()
        self._in_request = True
        try:
            ok, why, extra = self._handle(content)
        except Exception as exc:  # noqa: BLE001 - nothing escapes into the kernel's comm loop
            ok, why, extra = False, f"not taken: {type(exc).__name__}: {exc}", {}
        finally:
            self._in_request = False
        self.n_requests += 1
        seq = content.get("seq") if isinstance(content, dict) else None
        client = content.get("client") if isinstance(content, dict) else None
        if isinstance(client, str):
            self._last_client = client
        ack = {"type": "ack", "seq": seq if isinstance(seq, int) else None,
               "client": client if isinstance(client, str) else None, "ok": ok, "message": why}
        try:
            update = self._flush()
        except Exception as exc:  # noqa: BLE001 - a picture that cannot be sent: say so
            update, ack["ok"], ack["message"] = None, False, f"not drawn: {type(exc).__name__}: {exc}"
        if "sync" in extra:
            if extra["sync"] != self.version:
                update = self._snapshot()
        elif "desc" in extra:
            ack["desc"], ack["id"] = extra["desc"], extra["id"]
        if update is not None:
            ack["update"] = update
        if not ack["ok"] and self.said is not None and self.said(ack["message"]):
            ack["said"] = True           # shown beside the canvas already: not a third time
        ack["ms"] = round((time.perf_counter() - t0) * 1e3, 1)     # the kernel's time (benchmarks)
        self.send(ack)
        if extra.get("extra") and ack["ok"] and self.playing:
            self._schedule_extra()
            self._schedule_idle()

    # ------------------------------------------------------------------ Play: two frames in flight
    def _schedule_extra(self) -> None:
        """Call ``on_tick`` once more halfway to the next tick (module docstring, Play)."""
        try:
            loop = asyncio.get_running_loop()
        except RuntimeError:       # no event loop (no kernel): one frame per tick
            return
        gap = self._tick_gap if self._tick_gap is not None else 0.0
        # never at once: the kernel hands a message that came during the frame (a Stop) to its
        # message loop one event-loop turn after reading it; at once, this frame would go first
        delay = min(max(0.5 * gap - self._tick_cost, EXTRA_MIN_S), 0.1)
        self._extra = loop.call_later(delay, self._extra_frame)

    def _cancel_extra(self) -> None:
        handle, self._extra = self._extra, None
        if handle is not None:
            handle.cancel()

    def _extra_frame(self) -> None:
        """The extra Play frame: ``on_tick`` outside a request; its picture goes as an update."""
        self._extra = None
        if not self.playing or self.on_tick is None or self._in_request:
            return
        try:
            with self.around():
                self.on_tick()
            self.n_extra_frames += 1
            self._schedule_idle()
        except PlanargeoError as exc:
            text = str(exc)
            self.send({"type": "halt", "message": "" if self.said is not None and self.said(text) else text})
        except Exception as exc:  # noqa: BLE001 - nothing escapes into the kernel's event loop
            self.send({"type": "halt", "message": f"not taken: {type(exc).__name__}: {exc}"})

    def _schedule_idle(self) -> None:
        """Play's work ahead (``on_idle``) as soon as the event loop is free (module docstring, Play)."""
        if self.on_idle is None:
            return
        try:
            loop = asyncio.get_running_loop()
        except RuntimeError:       # no event loop (no kernel): the frames do the work themselves
            return
        loop.call_soon(self._idle)

    def _idle(self) -> None:
        if not self.playing or self.on_idle is None or self._in_request:
            return
        try:
            self.on_idle(IDLE_SLICE)
        except Exception:  # noqa: BLE001 - work ahead only: the frame that needs it reports a failure
            pass
