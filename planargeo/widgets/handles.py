"""Handles and dragging: points of the picture the user (or a test) drags to set controls.

The page sends ``{"type": "drag", "id", "x", "y"}`` messages; :meth:`HandleMixin.drag` sends the
same from Python, through the same check (``PictureCanvas.handle_message``).
"""
from __future__ import annotations

import math
import numbers
from dataclasses import dataclass
from typing import Any, Callable

import ipywidgets as W
import numpy as np

from planargeo.errors import InputError, PlanargeoError
from planargeo.widgets.controls import short_text

__all__ = ["Handle", "HandleMixin"]


@dataclass
class Handle:
    """A point of the picture the user drags in the page, and tests drag with :meth:`HandleMixin.drag`.

    Parameters
    ----------
    name : str
        Name of the handle (unique within an explorer).
    where : callable () -> (x, y) or None
        The handle's current data position; None when it cannot be dragged now.
    drag : callable (x, y) -> dict
        The control values that a drag to ``(x, y)`` means (a PlanargeoError: the step is refused).

    Examples
    --------
    >>> h = Handle("P", lambda: (0.0, 0.0), lambda x, y: {"P x": x, "P y": y})
    >>> h.drag(1.0, 2.0)
    {'P x': 1.0, 'P y': 2.0}
    """

    name: str
    where: Callable[[], Any]
    drag: Callable[[float, float], dict]


class HandleMixin:
    """Dragging for :class:`~planargeo.widgets.base.Explorer` (handles and drags, as the page sends them)."""

    def mechanism_points(self) -> np.ndarray:
        """Points ``(n, 2)`` the view must hold: by default the finite positions of the handles.

        Returns
        -------
        numpy.ndarray
        """
        pts = [(h["x"], h["y"]) for h in self._handle_list()]
        return np.array(pts, dtype=float).reshape(-1, 2)

    def all_handles(self) -> list[Handle]:
        """The explorer's :meth:`handles` (what the picture shows and drags use).

        Returns
        -------
        list of Handle
        """
        return list(self.handles())

    def handle_position(self, name: str):
        """Where handle ``name`` is now (None: it cannot be dragged now).

        Parameters
        ----------
        name : str
            A handle's name (:meth:`handles`).

        Returns
        -------
        (float, float) or None

        Raises
        ------
        InputError
            No handle of that name.
        """
        return self._handle(name).where()

    def _handle(self, name: str) -> Handle:
        found = {h.name: h for h in self.all_handles()}
        if name not in found:
            raise InputError(f"name must name a handle of {type(self).__name__} "
                             f"(handles: {', '.join(found) or 'none'}), got {name!r}")
        return found[name]

    def drag(self, name: str, start, end, steps: int = 10) -> "Explorer":
        """Drag handle ``name`` from ``start`` to ``end`` in ``steps`` moves, as the page does.

        Each move is one update or one refusal (named in :attr:`message`); values are not snapped.

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
            ``self``, dragged.

        Raises
        ------
        InputError
            No such handle, one not draggable now, bad points, or ``steps`` not a positive integer.
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
        self._drag_active = h                                    # the pointer's press on the handle
        try:
            for k in range(1, steps + 1):                        # its moves, as the page sends them
                p = a + (b - a) * (k / steps)
                self._drag_message(name, float(p[0]), float(p[1]))
        finally:
            self._release()                                      # and its release
        return self

    def _drag_message(self, name: str, x: float, y: float) -> bool:
        """One drag move sent as the page sends it, checked by the (page's or a headless) canvas."""
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
            try:   # a handle that cannot say where it is, or is not at a finite point: not shown
                p = h.where()
                if p is None:
                    continue
                if type(p) is tuple and len(p) == 2 and type(p[0]) is float and type(p[1]) is float:
                    x, y = p          # (most handles: two floats already)
                else:
                    x, y = (float(v) for v in np.asarray(p, dtype=float).reshape(2))
            except Exception:  # noqa: BLE001
                continue
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
        before = self.n_refusals
        self.set(**vals)
        return self.n_refusals == before

    def _page_drag(self, name: str, x: float, y: float) -> None:
        """A drag request from the page: one update, or a refusal the page shows."""
        if not self._drag_to(self._handle(name), x, y):
            raise PlanargeoError(self.message or f"drag of {name} refused")

    def _page_release(self, name: str) -> None:
        """The page's drag of ``name`` ended: as the end of a :meth:`drag` from Python."""
        self._drag_active = self._handle(name)
        self._release()

    def _release(self) -> None:
        """End of a :meth:`drag`: the shown state drawn again as a fresh explorer would draw it."""
        h, self._drag_active = self._drag_active, None
        if h is None or self.state is None:
            return
        message = self._message
        self._update()                             # no control changed: a render of the shown state
        if message and not self._message:          # a refused last step keeps its message
            self._set_message(message)
            self._figure_text = short_text(message)
            self._safe_redraw()
