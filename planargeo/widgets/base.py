"""The :class:`Explorer` base class shared by every interactive explorer.

An explorer is a scene made interactive (the hooks a subclass writes: :class:`Explorer`).  Its
parts, one job each: :mod:`~planargeo.widgets.controls`, :mod:`~planargeo.widgets.handles`,
:mod:`~planargeo.widgets.play`, :mod:`~planargeo.widgets.export`, :mod:`~planargeo.widgets.front`;
this module: the state, its updates and refusals.  A value that cannot be shown is *refused*: the
message names the control and the reason, and controls, picture and readout stay on the last
computed state; no exception escapes a callback.

Examples
--------
Two equal and opposite rotations add up to a translation (thesis 4.2); a zero
rotation is refused with a message, not an exception:

>>> from planargeo.widgets import ScrewSumExplorer
>>> ex = ScrewSumExplorer(display="agg")
>>> ex.controls["size2"].value = -1.0
>>> ex.readout_values["pole of sum"].startswith("at infinity")
True
>>> ex.controls["size2"].value = 0.0
>>> ex.message.startswith("ω₂ = 0 rad/s makes v₂ the zero twist")
True
>>> ex.controls["size2"].value, ex.readout_values["pole of sum"].startswith("at infinity")  # as shown
(-1.0, True)
"""
from __future__ import annotations

import contextlib
import time
import warnings
from pathlib import Path
from typing import Any, Callable

import ipywidgets as W
import numpy as np

from planargeo.draw.style import EXPLORER_DPI
from planargeo.errors import InputError, PlanargeoError
from planargeo.widgets.controls import (TEXT_LIMIT, Choice, ControlsMixin, Step, Toggle, cached,
                                         check_control, numeric_failure, same_value, short_text,
                                         shown_as)
from planargeo.widgets.export import ExportMixin
from planargeo.widgets.front import FrontMixin
from planargeo.widgets.handles import Handle, HandleMixin
from planargeo.widgets.play import DRAG_SYNC_S, PlayMixin
from planargeo.widgets.readout import fmt, point_text

__all__ = ["Explorer", "Handle", "Step", "Choice", "Toggle", "cached", "check_control", "fmt", "point_text",
           "TEXT_LIMIT"]

_DISPLAYS = ("auto", "ipympl", "image", "agg", "page")


class Explorer(ControlsMixin, FrontMixin, HandleMixin, PlayMixin, ExportMixin):
    """Base class: controls + picture + readout + message, one consistent state.

    Subclasses implement

    * :meth:`make_controls` -> ``{name: description or widget}`` (descriptions: :class:`Step`,
      :class:`Choice`, :class:`Toggle`; initial values are the defaults),
    * :meth:`compute` ``(values, changed) -> state``: may raise PlanargeoError,
    * :meth:`scene_picture` ``(state, view) -> Picture``: what is drawn,
    * :meth:`readout_of` ``(state) -> dict``: the numbers shown,
    * optionally :meth:`handles`, :meth:`play_step`, :meth:`adjust`, :meth:`disabled`,
      :meth:`explain` and :meth:`focus_options`.

    Controls in :attr:`display_controls` change the drawing only (no :meth:`compute`).
    :attr:`shown_values` are the control values of the state on show.

    Parameters
    ----------
    display : {"auto", "page", "image", "agg"}
        ``"page"`` (the browser draws the picture; ``"auto"``), ``"image"`` (a PNG) or ``"agg"``
        (nothing shown: tests).
    figsize : (float, float)
        Picture size in inches (at ``dpi``).
    export_dir : str or Path, optional
        Where *Export SVG* writes (default: the current directory).
    **values
        Initial control values overriding the defaults (and *Reset*'s).

    Raises
    ------
    InputError
        An unknown control or display, or an initial value the control does not take.
    PlanargeoError
        The initial values describe a state that cannot be computed.
    """

    #: Title shown above the explorer.
    title: str = "Explorer"

    #: Short name used for exported file names.
    slug: str = "explorer"

    #: Picture size (inches) and resolution (pixels per inch) of the picture and its images.
    figsize: tuple[float, float] = (6.0, 5.0)
    dpi: int = EXPLORER_DPI

    #: Controls that only change what is drawn (no recompute when only they change).
    #: The base adds ``"key"`` (legend) and, with :meth:`focus_options`, ``"focus"``.
    display_controls: tuple[str, ...] = ()

    #: Unit of each readout entry (shown beside the value; "—": dimensionless, nothing shown).
    units: dict[str, str] = {}

    #: Scene length scale: readout numbers below ``zero_tol * scale`` print as 0 (round-off).
    scale: float = 1.0
    zero_tol: float = 1e-9

    #: Frames per second of Play and of exported animations (``dt = speed / play_fps``).
    play_fps: int = 20

    #: Simulated seconds per wall-clock second at Play speed "1×" (shown beside the speed menu when not 1).
    time_scale: float = 1.0

    #: While the page drags a handle, controls, readout and message reach it at most this often
    #: (seconds; the picture follows every step), and at once at the drag's release or a refused
    #: step.  0: with every picture.
    drag_sync_s: float = DRAG_SYNC_S

    #: The wall clock Play reads (seconds; a test may give the explorer its own).
    wall_clock: Callable[[], float] = staticmethod(time.monotonic)

    def __init__(self, *, display: str = "auto", figsize=None, export_dir=None, **values):
        if display not in _DISPLAYS:
            raise InputError(f"display must be one of {_DISPLAYS}, got {display!r}")
        #: every explorer draws its own picture (kept for callers that ask)
        self.native = True
        self.display_mode = "page" if display in ("auto", "ipympl") else display   # ipympl: old notebooks
        self._figsize = self._figure_inches(figsize or self.figsize)
        self._figure_text = ""
        self._page_view = None
        self.export_dir = Path(export_dir) if export_dir is not None else None
        self.readout_values: dict[str, Any] = {}
        self.state: Any = None
        self.shown_values: dict[str, Any] = {}
        self.n_updates = self.n_computes = self.n_refusals = 0
        self.last_export: Path | None = None
        self._message = ""
        self._hold = self._quiet = 0
        self._drag_step = self._sync_now = False
        self._pending = self._busy = self._resetting = self._exporting = False
        self._changed: set[str] = set()
        self._echo: dict[str, list] = {}
        self._shadow: dict[str, tuple[float, float]] = {}
        self._drag_active: Handle | None = None
        self._drag_canvas = None
        self._drag_seq = 0
        self._make_controls(values)

        # widgets, Play (no figure: the picture is built from the state)
        self._make_widgets()
        self._tooltips = {k: getattr(w, "tooltip", None) for k, w in self.controls.items()}
        self.has_play = type(self).play_step is not Explorer.play_step
        self._make_play_controls()
        for name, w in self.controls.items():
            w.observe(self._make_observer(name), names="value")
        self.widget = self._layout()
        self._connect_page_play()
        self._update(initial=True)
        self.defaults = dict(self.values)  # as first shown (controls that follow others included)

    def make_controls(self) -> dict[str, W.ValueWidget]:  # pragma: no cover - abstract
        """The explorer's controls (subclasses).

        Returns
        -------
        dict
            ``{name: description or widget}``; the initial values are the defaults.

        Raises
        ------
        NotImplementedError
            In the base class.
        """
        raise NotImplementedError

    #: the explorer's own view ``(x0, x1, y0, y1)`` (its pictures may use it as their default)
    limits: tuple[float, float, float, float] | None = None

    def compute(self, values: dict[str, Any], changed: set[str]) -> Any:  # pragma: no cover
        """The scene's numbers for the control ``values`` (subclasses).

        Parameters
        ----------
        values : dict
            Every control's value.
        changed : set of str
            The controls that changed since the shown state (all of them at first).

        Returns
        -------
        Any
            The state :meth:`scene_picture` draws and :meth:`readout_of` reads.

        Raises
        ------
        PlanargeoError
            The values describe a state that cannot be shown (the update is refused).
        """
        raise NotImplementedError

    def scene_picture(self, state: Any, view=None):
        """The picture of ``state`` (subclasses); the base adds handles, key and message.

        Parameters
        ----------
        state : Any
            What :meth:`compute` returned.
        view : (x0, x1, y0, y1), optional
            The view the user zoomed or panned to (None: the explorer's own).

        Returns
        -------
        Picture

        Raises
        ------
        NotImplementedError
            In the base class.
        """
        raise NotImplementedError

    def readout_of(self, state: Any) -> dict[str, Any]:
        """The readout of ``state`` (subclasses).

        Parameters
        ----------
        state : Any
            What :meth:`compute` returned.

        Returns
        -------
        dict
            Readout entries ``{name: value}`` (names starting with ``_`` are not shown).

        Raises
        ------
        NotImplementedError
            In the base class.
        """
        raise NotImplementedError

    @property
    def native_page(self) -> bool:
        """True: every explorer draws its own picture (kept for old callers)."""
        return True

    def adjust(self, values: dict[str, Any], changed: set[str]) -> dict[str, Any]:
        """Values of controls that follow the ``changed`` ones, set and refused with them.

        Parameters
        ----------
        values : dict
            Every control's value.
        changed : set of str
            The controls that changed.

        Returns
        -------
        dict
            ``{name: value}`` of the controls that follow.
        """
        return {}

    def handles(self) -> list[Handle]:
        """The draggable handles of the picture (default: none).

        Returns
        -------
        list of Handle
            Each a point the user drags, with the control values a drag sets.
        """
        return []

    def play_step(self, values: dict[str, Any], dt: float) -> dict[str, Any] | None:
        """Control values of the next Play frame after ``values``, ``dt`` seconds on (None: stop).

        An explorer that overrides this gets Play and animation export.

        Parameters
        ----------
        values : dict
            The shown control values.
        dt : float
            Time step (s).

        Returns
        -------
        dict or None
        """
        return None

    def disabled(self, values: dict[str, Any]) -> dict[str, str]:
        """Controls that would change nothing in the state of ``values``, with the reason.

        Parameters
        ----------
        values : dict
            The shown control values.

        Returns
        -------
        dict
            ``{control name: reason}``, e.g. ``{"slide": "only prismatic joints slide"}``.
        """
        return {}

    def explain(self) -> dict[str, str]:
        """``{symbol or readout name: one-line meaning and thesis equation}``, for "what is shown".

        Returns
        -------
        dict
        """
        return {}

    def focus_options(self) -> list[str]:
        """Names of bodies or joints to focus on (none: no "focus" control); read after each update.

        Returns
        -------
        list of str
            The choices of the "focus" menu after "all", in menu order.
        """
        return []

    @property
    def message(self) -> str:
        """The message shown ("" when the last update succeeded)."""
        return self._message

    @contextlib.contextmanager
    def hold(self):
        """Change several controls with a single update at the end.

        Yields
        ------
        Explorer
            ``self``.
        """
        with self._page_after():
            self._hold += 1
            try:
                yield self
            finally:
                self._hold -= 1
                if self._hold == 0 and self._pending:
                    self._pending = False
                    self._update()

    @contextlib.contextmanager
    def _page_after(self):
        """The controls', readout's and message's new values reach the page after the picture."""
        if getattr(self, "_after_depth", 0):     # already held (a drag's reply, then its update)
            yield
            return
        self._after_depth = 1
        self._drag_step = self._sync_now = False
        stack = contextlib.ExitStack()
        try:
            for w in [*self.controls.values(), self.readout, self.message_box]:
                stack.enter_context(w.hold_sync())
            yield
        finally:
            self._after_depth = 0
            dragging = self._drag_step and not self._sync_now
            self._drag_step = self._sync_now = False
            # while the page plays or drags the syncs wait longer (PlayMixin._keep_hold): at most
            # every PLAY_SYNC_S or drag_sync_s seconds, and at once after the drag or a refusal
            # (a hold inside such a hold holds nothing of its own)
            if not self._keep_hold(stack, dragging):
                stack.close()

    def _page_drag(self, name: str, x: float, y: float) -> None:
        """A drag step from the page (HandleMixin's): the controls', readout's and message's values
        held with those of the drag's earlier steps (at most ``drag_sync_s``; the picture goes at
        once), sent at the drag's release or a refusal."""
        with self._page_after():      # the page's request holds already; a drag from Python: here
            self._drag_step = True
            super()._page_drag(name, x, y)

    def set(self, **values) -> "Explorer":
        """Set several controls at once (one update); if one value is refused, none is set.

        Parameters
        ----------
        **values
            ``name=value`` for each control to set.

        Returns
        -------
        Explorer
            ``self``; a bad name or value is refused and shown in :attr:`message`, never raised.
        """
        problems = []
        for k, v in values.items():
            if k not in self.controls:
                problems.append(f"unknown control {k!r} (controls: {', '.join(self.controls)})")
                continue
            try:
                values[k] = check_control(k, self.controls[k], v)
            except InputError as exc:
                problems.append(str(exc))
        if problems:
            self._refuse("; ".join(problems))
            return self
        with self.hold():
            for k, v in values.items():
                self.controls[k].value = v
        return self

    def reset(self) -> None:
        """Return every control to its default, the values first shown (one update), and Play's
        speed and loop to theirs (1×, looping)."""
        self._resetting = True
        try:
            with self.hold():
                for k, v in self.defaults.items():
                    self.controls[k].value = v
                self._reset_play()
                self._pending = True
        finally:
            self._resetting = False

    def _update(self, initial: bool = False) -> None:
        """Show the state of the controls, or refuse it; never raises after construction."""
        if self._busy:  # a re-entrant change from inside an update: fold it in
            self._pending = True
            return
        self._busy = True
        changed = set(self.controls) if initial else set(self._changed)
        self._changed.clear()
        try:
            with self._page_after():
                self._show(changed, initial)
        finally:
            self._busy = False
        if self._pending and not self._hold:
            self._pending = False
            self._update()

    def _show(self, changed: set[str], initial: bool) -> None:
        """Compute and render the controls' state, or refuse it (:meth:`_refuse`)."""
        values = self.values
        try:
            for k in changed:
                if not (self._resetting and same_value(values[k], self.defaults.get(k))):
                    values[k] = check_control(k, self.controls[k], values[k])
        except InputError as exc:
            if initial:
                raise
            self._refuse(str(exc), self.figure_message(exc))
            return
        try:
            follow = self.adjust(values, changed)
            self._set_controls(follow)
            values.update(follow)
            focus = self._focus_follow(values)
            self._set_controls(focus)
            values.update(focus)
            with warnings.catch_warnings():
                warnings.simplefilter("error", RuntimeWarning)
                if changed <= set(self.display_controls) and not initial:
                    state = self.state
                else:
                    self.n_computes += 1
                    state = self.compute(values, changed | set(follow))
                readout = dict(self.readout_of(state))
                table = self._readout_html(readout)
                message = (state.get("message", "") if isinstance(state, dict)
                           else getattr(state, "message", ""))
        except KeyboardInterrupt:   # Ctrl-C in a long compute: back to the shown state, then stop
            if initial:
                raise
            self._refuse("stopped by Ctrl-C before this was computed; the controls show the last "
                         "computed state (set a value again to compute it)")
            raise
        except Exception as exc:  # noqa: BLE001 - refused and reported, never raised
            if initial:
                raise
            said = [shown_as(w, w.value) for k, w in self.controls.items() if k in changed]
            refused = ", ".join(f"{n} = {v}" for n, v in said                # unless the reason says it
                                if f"{n} = {v.split()[0]}" not in str(exc) and not (v[:1] == "“" and v[1:-1] in str(exc)))
            reason = self._reason(exc)
            if numeric_failure(exc) and refused:
                reason = (f"{refused} cannot be computed: a number left double precision's range "
                          f"({exc}); choose a smaller magnitude")
                figure = short_text(reason)
            else:
                figure = self.figure_message(exc)
            self._refuse(f"{reason} (refused: {refused})" if refused else reason, figure)
            self._follow_shown()
            return
        self.state = state
        self.shown_values = self.values
        self.readout_values = readout
        self.readout.value = table
        self._set_message(message)
        self._figure_text = message
        self._follow_shown()
        self.n_updates += 1
        self._safe_redraw()

    @staticmethod
    def _reason(exc: Exception) -> str:
        if isinstance(exc, PlanargeoError):
            return str(exc)
        if isinstance(exc, (ArithmeticError, RuntimeWarning, np.linalg.LinAlgError, ValueError)):
            return f"cannot compute this configuration: {exc}"
        return f"internal error ({type(exc).__name__}): {exc}"

    def _refuse(self, message: str, figure_text: str | None = None) -> None:
        """Report ``message`` and return controls, picture and readout to the shown state."""
        self.n_refusals += 1
        if getattr(self, "_after_depth", 0):
            self._sync_now = True      # a drag's held values go after this update's picture
        elif getattr(self, "_play_hold", None) is not None:
            self._release_play_hold()  # ... or now (no update around: nothing goes before them)
        reverted = [k for k, v in self.shown_values.items()
                    if k in self.controls and not same_value(self.controls[k].value, v)]
        self._set_controls(self.shown_values)
        for k in reverted:  # tell the browser even while it is sending this very control
            with contextlib.suppress(Exception):
                self.controls[k].send_state("value")
        self._changed.clear()
        self._pending = False
        self._set_message(message)
        self._figure_text = short_text(message) if figure_text is None else figure_text
        self._safe_redraw()

    def figure_message(self, exc: Exception) -> str:
        """Short text written on the picture when an update is refused.

        Parameters
        ----------
        exc : Exception
            What refused the update.

        Returns
        -------
        str
            The reason, whole (the picture wraps it onto lines).
        """
        return short_text(self._reason(exc))

    def _safe_redraw(self) -> None:
        if self._exporting:  # frames of an animation are drawn by the exporter
            return
        try:
            self.redraw()
        except Exception as exc:  # noqa: BLE001
            self._message = self._message or f"drawing failed ({type(exc).__name__}): {exc}"

    def _cache(self, name: str) -> dict:
        """The explorer's own cache ``name``, a dict made at its first use (see :func:`cached`)."""
        return self.__dict__.setdefault(name, {})

    def guarded(self, callback: Callable) -> Callable:
        """``callback`` for a button or the page: an exception becomes a message, never escapes.

        Parameters
        ----------
        callback : callable

        Returns
        -------
        callable
            Takes ``callback``'s arguments and gives its result, or None after an error (shown).
        """
        def run(*args):
            try:
                return callback(*args)
            except Exception as exc:  # noqa: BLE001 - a callback must never raise
                self._set_message(f"internal error ({type(exc).__name__}): {exc}")

        return run

    def time_update(self, name: str, values: list, repeat: int = 1) -> list[float]:
        """Seconds from setting ``controls[name]`` to the new state shown (its picture sent), per value.

        Parameters
        ----------
        name : str
            The control to set.
        values : list
            Values to set in turn.
        repeat : int
            How many times to go through ``values``.

        Returns
        -------
        list of float
        """
        out = []
        for _ in range(repeat):
            for v in values:
                t0 = time.perf_counter()
                self.controls[name].value = v
                out.append(time.perf_counter() - t0)
        return out
