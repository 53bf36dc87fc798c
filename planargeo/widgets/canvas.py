"""The page renderer's widget: a picture drawn by the browser, handles dragged in the page.

:class:`PictureCanvas` is an `anywidget <https://anywidget.dev>`_ whose ES module
(``canvas.js``, shipped beside this file: no build step, no network) draws a
picture's plain data (:mod:`planargeo.draw.picture`) as SVG.  The page moves a
dragged handle, zooms and pans at once, and sends the kernel one request at a time:

``{"type": "drag", "id": str, "x": float, "y": float, "seq": int}``
    a handle moved to ``(x, y)`` (data coordinates);
``{"type": "view", "box": [x0, x1, y0, y1] | None, "seq": int}``
    the user zoomed or panned (None: back to the explorer's own view);
``{"type": "ping", "seq": int}``
    nothing to do (the floor of a round trip, for benchmarks).

Every message is checked here before anything acts on it (its type, its fields'
types, finite numbers within :data:`COORD_LIMIT`, a known handle); a bad one is
answered ``ok: false`` and changes nothing.  The kernel answers each request with
``{"type": "ack", "seq", "ok", "message"}`` after the new picture (if any) is set,
so the page knows when it may send the next.

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
"""
from __future__ import annotations

import math
import numbers
from pathlib import Path
from typing import Any, Callable

import anywidget
import traitlets

from planargeo.errors import PlanargeoError

__all__ = ["PictureCanvas", "COORD_LIMIT"]

#: Largest coordinate (in absolute value) a message from the page may carry.
COORD_LIMIT = 1e9

_CSS = """
.pg-canvas { position: relative; font-family: 'DejaVu Sans', sans-serif; user-select: none; }
.pg-canvas svg { display: block; touch-action: none; outline: none; }
.pg-bar { display: flex; gap: 8px; align-items: center; height: 24px; font-size: 12px; }
.pg-bar button { font-size: 12px; padding: 1px 8px; }
.pg-status { color: #b00020; white-space: nowrap; overflow: hidden; text-overflow: ellipsis; }
.pg-bg { fill: white; }
.pg-frame { fill: none; stroke: #444; stroke-width: 1; pointer-events: none; }
.pg-axes line { stroke: #444; stroke-width: 1; }
.pg-axes text, .pg-title { fill: #222; }
.pg-el.pg-faded { opacity: 0.18; }
.pg-el.pg-hover path, .pg-el.pg-hover line { stroke-width: 3; }
.pg-handle { fill: rgba(0, 0, 0, 0); stroke: rgba(0, 0, 0, 0.35); stroke-width: 1; cursor: grab; }
.pg-handle:hover, .pg-handle.pg-dragging { stroke: #000; stroke-width: 1.6; fill: rgba(255, 255, 0, 0.25); }
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


class PictureCanvas(anywidget.AnyWidget):
    """A picture drawn in the page (module docstring).

    Parameters
    ----------
    on_drag : callable ``(handle id, x, y) -> None``, optional
        Called for a checked drag request; raise a :class:`~planargeo.errors.PlanargeoError`
        to refuse the position (the page snaps the handle back and shows the reason).
    on_view : callable ``(box or None) -> None``, optional
        Called for a checked zoom / pan / reset request.
    **kwargs
        Passed to :class:`anywidget.AnyWidget`.

    Attributes
    ----------
    picture : dict
        The picture's data (:meth:`planargeo.draw.picture.Picture.to_dict`); setting it
        redraws the page.
    n_requests : int
        Requests answered so far.
    """

    _esm = Path(__file__).with_name("canvas.js")
    _css = _CSS
    picture = traitlets.Dict().tag(sync=True)

    def __init__(self, on_drag: Callable[[str, float, float], Any] | None = None,
                 on_view: Callable[[Any], Any] | None = None, **kwargs):
        super().__init__(**kwargs)
        self.on_drag = on_drag
        self.on_view = on_view
        self.n_requests = 0
        self.on_msg(self._on_msg)

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
            Whatever ``on_drag`` or ``on_view`` raise other than a
            :class:`~planargeo.errors.PlanargeoError` (a refusal); the widget answers
            such a request as not taken, and the exception goes no further.
        """
        try:
            if not isinstance(msg, dict):
                raise PlanargeoError(f"a message must be a dict, got {type(msg).__name__}")
            kind = msg.get("type")
            if kind == "ping":
                return True, ""
            if kind == "drag":
                hid = msg.get("id")
                if not isinstance(hid, str) or hid not in {h.get("id") for h in
                                                           self.picture.get("handles", [])}:
                    raise PlanargeoError(f"no handle {hid!r} in the picture")
                x, y = _finite("x", msg.get("x")), _finite("y", msg.get("y"))
                if self.on_drag is not None:
                    self.on_drag(hid, x, y)
                return True, ""
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
                return True, ""
            raise PlanargeoError(f"unknown message type {kind!r}")
        except PlanargeoError as exc:
            return False, str(exc)

    def _on_msg(self, _widget, content, _buffers) -> None:
        try:
            ok, why = self.handle_message(content)
        except Exception as exc:  # noqa: BLE001 - nothing escapes into the kernel's comm loop
            ok, why = False, f"not taken: {type(exc).__name__}: {exc}"
        self.n_requests += 1
        seq = content.get("seq") if isinstance(content, dict) else None
        self.send({"type": "ack", "seq": seq if isinstance(seq, int) else None, "ok": ok, "message": why})
