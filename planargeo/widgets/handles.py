"""Handles and dragging: points of the picture the user (or a test) drags to set controls.

A :class:`Handle` names a point, where it is now, and the control values a drag to a
new point means.  :class:`HandleMixin` gives the explorer :meth:`~HandleMixin.drag`
(in every display mode, through the same checked message the page sends) and, for
an explorer still drawn by matplotlib artists, the mouse on its figure.

Examples
--------
>>> h = Handle("P", lambda: (0.0, 0.0), lambda x, y: {"P x": x, "P y": y})
>>> h.drag(1.0, 2.0)
{'P x': 1.0, 'P y': 2.0}
"""
from __future__ import annotations

import contextlib
import math
import numbers
import time
from dataclasses import dataclass
from typing import Any, Callable

import ipywidgets as W
import numpy as np

from planargeo.errors import InputError, PlanargeoError
from planargeo.widgets.controls import short_text

__all__ = ["Handle", "HandleMixin"]


@dataclass
class Handle:
    """A point of the figure the mouse can drag (under ipympl) and tests can drag (:meth:`Explorer.drag`).

    Parameters
    ----------
    name : str
        Name of the handle (unique within an explorer), used by :meth:`Explorer.drag`.
    where : callable () -> (x, y) or None
        The handle's current data position; None when it cannot be dragged now.
    drag : callable (x, y) -> dict
        The control values that a drag to the data point ``(x, y)`` means.  It may
        raise a :class:`~planargeo.errors.PlanargeoError`: the drag step is refused,
        the last good state stays, and the message names the reason.

    """
    name: str
    where: Callable[[], Any]
    drag: Callable[[float, float], dict]


class HandleMixin:
    """Dragging for :class:`~planargeo.widgets.base.Explorer` (handles, drags, the figure's mouse)."""

    def mechanism_points(self) -> np.ndarray:
        """Points ``(n, 2)`` the view must hold: by default the finite positions of the handles.

        An explorer whose mechanism has more to keep in view (links, bodies) may
        add them; the rule tests check that the view contains these points and
        is never much smaller than :attr:`scale`.

        Returns
        -------
        numpy.ndarray
            ``(n, 2)`` data points.
        """
        pts = []
        for h in self.all_handles():
            with contextlib.suppress(Exception):
                xy = h.where()
                if xy is not None:
                    q = np.asarray(xy, dtype=float).reshape(2)
                    if np.all(np.isfinite(q)):
                        pts.append(q)
        return np.array(pts, dtype=float).reshape(-1, 2)

    def connect_drag(self, x_control: str, y_control: str, target: Callable[[], Any],
                     radius_px: float | None = None) -> None:
        """Let the mouse drag the point ``target()`` (data ``(x, y)``) by setting two controls.

        Kept for compatibility: it adds a :class:`Handle` named ``"x_control,y_control"``.

        Parameters
        ----------
        x_control, y_control : str
            The controls that take the dragged point's x and y.
        target : callable () -> (x, y) or None
            The point's current position.
        radius_px : float, optional
            Pick radius in pixels (default :attr:`handle_radius_px`).
        """
        if radius_px is not None:
            self.handle_radius_px = float(radius_px)
        self._extra_handles.append(Handle(f"{x_control},{y_control}", target,
                                          lambda x, y: {x_control: x, y_control: y}))

    def all_handles(self) -> list[Handle]:
        """:meth:`handles` and those added by :meth:`connect_drag`.

        Returns
        -------
        list of Handle
        """
        return list(self.handles()) + list(self._extra_handles)

    def _handle(self, name: str) -> Handle:
        found = {h.name: h for h in self.all_handles()}
        if name not in found:
            raise InputError(f"name must name a handle of {type(self).__name__} "
                             f"(handles: {', '.join(found) or 'none'}), got {name!r}")
        return found[name]

    def drag(self, name: str, start, end, steps: int = 10) -> "Explorer":
        """Drag handle ``name`` from data point ``start`` to ``end`` in ``steps`` moves.

        Works in every display mode, as the mouse does under ipympl: each move is
        one update (or one refusal, which keeps the last good state and names the
        reason in :attr:`message`); values are not snapped to the sliders' grid.
        The handle follows the pointer: move ``k`` asks ``drag`` of the point
        ``start + (end - start) k / steps``.

        Parameters
        ----------
        name : str
            A handle's name (:meth:`handles`).
        start, end : (float, float)
            Data points where the drag starts and ends.
        steps : int
            Number of moves (updates).

        Returns
        -------
        Explorer
            ``self``.

        Raises
        ------
        InputError
            No handle of that name, the handle cannot be dragged now, a start or
            end that is not two finite numbers, or ``steps`` not a positive integer.
        """
        h = self._handle(name)
        if not isinstance(steps, numbers.Integral) or isinstance(steps, bool) or steps < 1:
            raise InputError(f"steps must be a positive integer, got {steps!r}")
        try:
            a = np.asarray(start, dtype=float).reshape(2)
            b = np.asarray(end, dtype=float).reshape(2)
        except (TypeError, ValueError):
            raise InputError(f"start and end must be points (x, y), got {start!r}, {end!r}") from None
        if not (np.all(np.isfinite(a)) and np.all(np.isfinite(b))):
            raise InputError(f"start and end must be finite, got {start!r}, {end!r}")
        if h.where() is None:
            raise InputError(f"handle {name!r} cannot be dragged in this state")
        self._drag_active, self._drag_pending = h, None          # the mouse's press on the handle
        try:
            for k in range(1, steps + 1):                        # its moves
                p = a + (b - a) * (k / steps)
                if self.native:     # as the page sends it: the canvas checks the message first
                    self._drag_message(name, float(p[0]), float(p[1]))
                else:
                    self._drag_to(h, float(p[0]), float(p[1]))
        finally:
            self._release()                                      # and its release
        return self

    def _drag_message(self, name: str, x: float, y: float) -> bool:
        """One drag move sent as the page sends it (``{"type": "drag", ...}``), in any display mode.

        The page's canvas (a headless one outside the page, holding the handles that
        can be dragged now) checks the message and calls :meth:`_page_drag`; a message
        it refuses is shown as a refused drag step.
        """
        if self.display_mode == "page":
            canvas = self.canvas
        else:
            if self._drag_canvas is None:
                self._drag_canvas = self._make_canvas()
            canvas = self._drag_canvas
            canvas.picture = {"handles": self._handle_list()}
        self._drag_seq += 1
        ok, why = canvas.handle_message({"type": "drag", "id": name, "x": x, "y": y,
                                         "seq": self._drag_seq})
        if not ok and why != self.message:   # refused by the check, before any update
            self._refuse(f"drag of {name} refused: {why}")
        return ok

    def _handle_list(self) -> list[dict]:
        """The handles that can be dragged now, as the picture lists them."""
        out = []
        for h in self.all_handles():
            try:
                where = h.where()
            except Exception:  # noqa: BLE001 - a handle that cannot say where it is: not shown
                where = None
            if where is None:
                continue
            x, y = (float(v) for v in np.asarray(where, dtype=float).reshape(2))
            if math.isfinite(x) and math.isfinite(y):
                out.append({"id": h.name, "x": x, "y": y})
        return out

    def _drag_to(self, h: Handle, x: float, y: float) -> bool:
        """One drag move: the handle's control values as one update (clamped to the sliders)."""
        try:
            vals = dict(h.drag(x, y))
        except Exception as exc:  # noqa: BLE001 - a refused drag step, never raised
            self._refuse(f"drag of {h.name} refused: {self._reason(exc)}", self.figure_message(exc))
            return False
        for k, v in vals.items():
            w = self.controls.get(k)
            real = isinstance(v, numbers.Real) and not isinstance(v, (bool, np.bool_))
            if isinstance(w, (W.FloatSlider, W.IntSlider)) and real and math.isfinite(v):
                v = min(max(float(v), w.min), w.max)
                vals[k] = int(round(v)) if isinstance(w, W.IntSlider) else v
        before = self.n_updates
        self.set(**vals)
        return self.n_updates > before

    def _page_drag(self, name: str, x: float, y: float) -> None:
        """A drag request from the page: one update, or a refusal the page shows."""
        if not self._drag_to(self._handle(name), x, y):
            raise PlanargeoError(self.message or f"drag of {name} refused")

    def _connect_handles(self) -> None:
        if self.fig is None:   # a native explorer: the page (or :meth:`drag`) sends drag messages
            return
        canvas = self.fig.canvas
        self._mouse_cids = getattr(self, "_mouse_cids", []) + [
            canvas.mpl_connect(ev, self.guarded(fn)) for ev, fn in (
                ("button_press_event", self._on_press), ("motion_notify_event", self._on_move),
                ("button_release_event", self._on_release))]

    def _on_press(self, ev) -> None:
        if ev.inaxes is not self.ax or ev.button not in (1, None):
            return
        tb = getattr(self.fig.canvas, "toolbar", None)
        if tb is not None and str(getattr(tb, "mode", "")):  # pan / zoom in use
            return
        best, dmin = None, float(self.handle_radius_px)
        for h in self.all_handles():
            xy = h.where()
            if xy is None or not np.all(np.isfinite(np.asarray(xy, float))):
                continue
            px = self.ax.transData.transform(np.asarray(xy, float))
            d = float(np.hypot(px[0] - ev.x, px[1] - ev.y))
            if d <= dmin:
                best, dmin = h, d
        self._drag_active = best

    #: a mouse move arriving within this many seconds of the end of a drag step that took longer
    #: than :attr:`DRAG_BACKLOG_COST` was queued behind it: it is kept and applied with the next
    #: move or the release, not drawn on its own (so the figure keeps up with the mouse)
    DRAG_BACKLOG_GAP = 0.008

    DRAG_BACKLOG_COST = 0.03

    def _on_move(self, ev) -> None:
        h = self._drag_active
        if h is None or ev.inaxes is not self.ax or ev.xdata is None:
            return
        x, y = ev.xdata, ev.ydata
        if not (np.isfinite(x) and np.isfinite(y)):
            return
        now = time.monotonic()
        last_end, last_cost = self._last_drag
        if last_cost > self.DRAG_BACKLOG_COST and now - last_end < self.DRAG_BACKLOG_GAP:
            self._drag_pending = (float(x), float(y))
            self._last_drag = (now, last_cost)
            return
        self._drag_pending = None
        self._drag_to(h, float(x), float(y))
        self._last_drag = (time.monotonic(), time.monotonic() - now)

    def _on_release(self, ev) -> None:
        self._release()

    def _release(self) -> None:
        """End of a drag (mouse or :meth:`drag`): the last queued move, then the shown state drawn
        again as a fresh explorer would draw it (a view held still during the drag is fitted)."""
        h, pending = self._drag_active, self._drag_pending
        if h is not None and pending is not None:  # the last position, queued behind a slow step
            self._drag_to(h, *pending)
        self._drag_active, self._drag_pending = None, None
        self._last_drag = (0.0, 0.0)
        if h is None or self.state is None:
            return
        message = self._message
        self._update()                             # no control changed: a render of the shown state
        if message and not self._message:          # a refused last step keeps its message
            self._set_message(message)
            self._show_figure_message(short_text(message))
            self._safe_redraw()
