"""The :class:`Explorer` base class shared by every interactive explorer.

An explorer is a small interactive figure: a matplotlib figure whose artists
are built **once**, a set of ipywidgets controls, a readout of the key numbers,
a message area, a *Reset* and an *Export SVG* button.  On every control change
it recomputes what its scene needs and updates its artists in place
(``set_data``, ``set_xy``...), then asks the canvas to redraw.

Physics and drawing are two steps: :meth:`Explorer.compute` (the scene's
numbers) and :meth:`Explorer.render` (artists and readout from them).  A
control listed in :attr:`Explorer.display_controls` (an overlay checkbox, a
construction toggle) only changes what is drawn: changing it re-renders the
last computed state without calling ``compute`` again.  Explorers also cache
what depends on a few controls only (a model, a shape's moments), so that a
change recomputes no more than its scene needs.

Two front ends are supported:

``"ipympl"``
    under ``%matplotlib widget`` the figure canvas is itself a widget, and the
    mouse can drag things on it;
``"image"``
    under the default inline backend the figure is rendered to PNG into an
    :class:`ipywidgets.Image` after every change;
``"agg"``
    no display at all (tests, benchmarks): the figure is drawn on an Agg canvas;
``"page"``
    the browser draws the picture (:mod:`planargeo.widgets.canvas`): the explorer's
    state becomes a picture of plain elements (:mod:`planargeo.draw.picture`), the
    page moves a dragged handle at once, zooms and pans, and asks the kernel for
    one new picture at a time; no pixels travel.

The default, ``display="auto"``, picks ``"ipympl"`` when that backend is
active and ``"image"`` otherwise.

One consistent state.  The controls, the figure and the readout always show
the same state: the one last computed.  A value that cannot be shown is
*refused*: a control set to NaN, out of its range, to ``None`` or to no option
of its list, or a combination the scene cannot compute (an impossible or
singular configuration, any :class:`~planargeo.errors.PlanargeoError`).  The
message area names the refused control and the reason, the controls return
to the shown values, and the figure and readout stay as they were.  No
exception ever escapes a callback.

Programmatic use (tests, notebooks)::

    ex.controls["angle"].value = 0.3     # triggers one update
    ex.readout_values["distance"]        # the numbers shown in the readout
    ex.message                           # "" when all is well
    with ex.hold():                      # several changes, one update
        ex.controls["a"].value = 1.0
        ex.controls["b"].value = 2.0

What the base adds to every explorer (issue 13):

* **Readout with units**: :attr:`Explorer.units` names each entry's unit; numbers
  below ``zero_tol * scale`` (round-off at the scene's size) print as ``0``.
* **Handles**: :meth:`Explorer.handles` lists :class:`Handle` objects; under
  ipympl a press within :attr:`Explorer.handle_radius_px` of one drags it, one
  update per mouse move, with no snapping to the sliders' grid and no echo of
  the sliders (a browser slider rounds a value to its step and sends it back:
  that copy is ignored).  :meth:`Explorer.drag` goes through the same press,
  moves and release without a mouse; the release draws the shown state again
  (a view held still during the drag is fitted as a fresh explorer fits it).
* **Play**: an explorer that defines :meth:`Explorer.play_step` gets a Play
  control with speed and loop; :meth:`Explorer.advance` steps it from Python.
  Play runs at true real time × speed × :attr:`Explorer.time_scale` (the factor
  is shown beside the speed menu when it is not 1): the wall clock sets the
  simulated time, reached through ``play_step`` sub-steps of at most
  ``1 / play_fps`` s (:mod:`planargeo.widgets.play`); only display frames drop.
  Runs are bounded: ``advance`` and ``export_animation`` refuse, by name, a
  count or duration that is not positive and finite or is beyond the stated
  limit (``allow_long=True`` opts in); Ctrl-C keeps what was computed.
* **Controls that say why not**: :meth:`Explorer.disabled` names the controls
  that would change nothing now, with the reason; they are disabled, the
  reason is their tooltip (the key too, when nothing drawn has an entry).
* **What is shown**: :meth:`Explorer.explain` gives the meaning of every symbol
  on screen, listed in a collapsible panel under the readout.
* **Readable numbers** (:mod:`planargeo.widgets.readout`): units only after
  numbers, one per component of a vector (a tuple in :attr:`Explorer.units`);
  :func:`point_text` for points (ideal ones by ``is_ideal``).  A number typed
  into a text field beyond :data:`TEXT_LIMIT`, or one that overflows inside
  the computation, is refused in the package's words, naming the control.
* **Focus and key**: :meth:`Explorer.focus_options` adds a ``"focus"`` dropdown
  (its options read again after every update: a focus gone falls back to "all");
  every explorer has a ``"key"`` checkbox that shows a legend of the labelled
  artists.  Both are display controls.
* **Export**: :meth:`Explorer.export_svg`, :meth:`Explorer.export_png`,
  :meth:`Explorer.export_animation` (GIF, or MP4 with ffmpeg) write files
  atomically; the buttons put a download link in the page.
* **Fast frames** (:mod:`planargeo.widgets.frames`): each update draws only what
  can change over a kept background (blitting), sends the page a 256-colour PNG
  (under ipympl at once, only the changed pixels, without ipympl's round trip
  through the page), and the controls' and readout's new values after the picture.
  Exports and the stored picture are drawn whole, at full colour.
* **Layout**: controls on the left; on the right a reserved message line, the
  figure at its native size (at least 560 px wide, shrinking with a narrow output
  area) and the readout under it, so that nothing moves as values change.
  Labels of the drawing avoid each other and stay inside the axes
  (:func:`planargeo.draw.artists.place_labels`).

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
>>> ex.message.endswith("(refused: size2 = 0)")
True
>>> ex.controls["size2"].value, ex.readout_values["pole of sum"].startswith("at infinity")  # as shown
(-1.0, True)
"""
from __future__ import annotations

import base64
import contextlib
import html
import io
import itertools
import math
import numbers
import os
import re
import shutil
import subprocess
import tempfile
import time
import warnings
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Callable

import ipywidgets as W
import matplotlib
import numpy as np
from matplotlib.figure import Figure
from traitlets import validate

from planargeo.draw.artists import has_legend_entries, place_labels
from planargeo.draw.style import EXPLORER_DPI, EXPLORER_MIN_WIDTH_PX, EXPLORER_TICK_PT, LABEL_PT, setup_axes
from planargeo.errors import InputError, OutputError, PlanargeoError
from planargeo.files import atomic_write
from planargeo.widgets import play as _play
from planargeo.widgets.frames import Frames, live_canvas, live_png
from planargeo.widgets.readout import explain_html, fmt, point_text, value_text

__all__ = ["Explorer", "Handle", "Step", "cached", "check_control", "fmt", "point_text", "TEXT_LIMIT"]

_DISPLAYS = ("auto", "ipympl", "image", "agg", "page")
_export_counter = itertools.count(1)


#: entries an explorer's per-parameter cache holds before it is emptied
CACHE_LIMIT = 32


def cached(cache: dict, key, make: Callable[[], Any]) -> Any:
    """``cache[key]``, built by ``make()`` when missing; a full cache (> :data:`CACHE_LIMIT`) is emptied.

    Explorers keep models or integrated shapes per parameter tuple with this, so
    a slider sweep over many values cannot grow a cache without bound.

    Parameters
    ----------
    cache : dict
        The explorer's cache.
    key : hashable
        The parameters the entry depends on.
    make : callable
        Builds the entry when it is missing.

    Returns
    -------
    Any
        The cached entry.

    Examples
    --------
    >>> store = {}
    >>> cached(store, (1.0, 2.0), lambda: "model"), cached(store, (1.0, 2.0), lambda: "other")
    ('model', 'model')
    >>> for k in range(40):
    ...     _ = cached(store, k, lambda: k)
    >>> len(store) <= CACHE_LIMIT + 1
    True
    """
    if key not in cache:
        if len(cache) > CACHE_LIMIT:
            cache.clear()
        cache[key] = make()
    return cache[key]


def _backend_is_ipympl() -> bool:
    name = matplotlib.get_backend().lower()
    return "ipympl" in name or name in ("widget", "module://ipympl.backend_nbagg")


class FloatSlider(W.FloatSlider):
    """A float slider that keeps a value outside its range, for the explorer to refuse by name.

    (An ipywidgets slider silently moves such a value to the nearest end.)
    """

    @validate("value")
    def _validate_value(self, proposal):
        return proposal["value"]


class IntSlider(W.IntSlider):
    """An integer slider that keeps a value outside its range (see :class:`FloatSlider`)."""

    @validate("value")
    def _validate_value(self, proposal):
        return proposal["value"]


class Step:
    """A slider description: ``Step(lo, hi, step, value, label, integer=False)``.

    Parameters
    ----------
    lo, hi : float
        Range of the slider.
    step : float
        Slider step (made finer by :meth:`make` when ``value`` is not on its grid).
    value : float
        Default value.
    label : str
        Description shown beside the slider.
    integer : bool
        An integer slider.
    """

    def __init__(self, lo: float, hi: float, step: float, value: float, label: str = "",
                 integer: bool = False):
        self.lo, self.hi, self.step, self.value, self.label = lo, hi, step, value, label
        self.integer = integer

    def make(self, name: str) -> FloatSlider | IntSlider:
        """The slider widget (a default off the grid makes the step finer: it must be shown exactly).

        Parameters
        ----------
        name : str
            Description used when the step has no label.

        Returns
        -------
        FloatSlider or IntSlider
        """
        step = self.step if self.integer else _representable_step(self.value, self.lo, self.step)
        cls, shown = (IntSlider, "d") if self.integer else (FloatSlider, f".{_decimals(step)}f")
        return cls(value=self.value, min=self.lo, max=self.hi, step=step,
                   description=self.label or name, continuous_update=True, readout_format=shown,
                   style={"description_width": "initial"}, layout=W.Layout(width="310px"))


_SELECTIONS = (W.Dropdown, W.ToggleButtons, W.RadioButtons, W.Select)


def check_control(name: str, widget, value):
    """``value`` as control ``name`` holds it, or :class:`InputError` naming the control.

    A slider takes a finite real number in its range (an integer slider an
    integral one), a list (dropdown, toggle buttons) one of its options, a
    checkbox ``True`` or ``False``, a text box a string whose numbers are at most
    :data:`TEXT_LIMIT` in magnitude (finite).

    Parameters
    ----------
    name : str
        The control's name (for the message).
    widget : ipywidgets.ValueWidget
        The control.
    value : Any
        The value to check.

    Returns
    -------
    Any
        The value as the control holds it (a float for a float slider, an int for an integer one).

    Raises
    ------
    InputError
        The control does not take the value.

    Examples
    --------
    >>> check_control("angle", Step(-180, 180, 1.0, 0.0).make("angle"), 30)
    30.0
    >>> check_control("angle", Step(-180, 180, 1.0, 0.0).make("angle"), float("nan"))
    Traceback (most recent call last):
    ...
    planargeo.errors.InputError: angle must be a number between -180 and 180, got nan
    >>> check_control("joints", W.Dropdown(options=("revolute", "prismatic")), None)
    Traceback (most recent call last):
    ...
    planargeo.errors.InputError: joints must be one of ['revolute', 'prismatic'], got None
    >>> check_control("joint speeds", W.Text(), "1, 1e150")
    Traceback (most recent call last):
    ...
    planargeo.errors.InputError: joint speeds: numbers typed here must lie between -1e+06 and 1e+06, got 1e150
    """
    if isinstance(widget, (W.FloatSlider, W.IntSlider)):
        integer = isinstance(widget, W.IntSlider)
        real = isinstance(value, numbers.Real) and not isinstance(value, (bool, np.bool_))
        x = float(value) if real else float("nan")
        if not (widget.min <= x <= widget.max and (x.is_integer() or not integer)):
            kind = "an integer" if integer else "a number"
            raise InputError(f"{name} must be {kind} between {widget.min:g} and {widget.max:g}, "
                             f"got {value!r}")
        return int(x) if integer else x
    if isinstance(widget, _SELECTIONS):
        options = [o[1] if isinstance(o, tuple) else o for o in widget.options]
        try:
            found = value in options
        except (TypeError, ValueError):  # an array compared with the options
            found = False
        if not found:
            raise InputError(f"{name} must be one of {options}, got {value!r}")
        return value
    if isinstance(widget, W.Checkbox):
        if not isinstance(value, (bool, np.bool_)):
            raise InputError(f"{name} must be True or False, got {value!r}")
        return bool(value)
    if isinstance(widget, W.Text):
        if not isinstance(value, str):
            raise InputError(f"{name} must be text, got {value!r}")
        for tok in _NUMBER.findall(value):
            x = float(tok)
            if not abs(x) <= TEXT_LIMIT:
                raise InputError(f"{name}: numbers typed here must lie between {-TEXT_LIMIT:g} and "
                                 f"{TEXT_LIMIT:g}, got {tok}")
    return value


#: the largest magnitude of a number typed into an explorer's text field (a larger one is refused
#: by name before any computation, instead of overflowing inside it)
TEXT_LIMIT = 1e6
_NUMBER = re.compile(r"(?<![\w.])[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?(?![\w.])|"
                     r"(?<![\w])[-+]?(?:inf(?:inity)?|nan)(?![\w])", re.IGNORECASE)


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

    Examples
    --------
    >>> h = Handle("P", lambda: (0.0, 0.0), lambda x, y: {"P x": x, "P y": y})
    >>> h.drag(1.0, 2.0)
    {'P x': 1.0, 'P y': 2.0}
    """

    name: str
    where: Callable[[], Any]
    drag: Callable[[float, float], dict]


def _grid_ok(value: float, lo: float, step: float) -> bool:
    """True when ``value`` lies on the slider grid ``lo + k step`` (what the front end shows)."""
    if not step or step <= 0:
        return True
    k = (value - lo) / step
    return abs(k - round(k)) <= 1e-6


def _on_grid(value: float, lo: float, step: float) -> float:
    """``value`` rounded to the grid ``lo + k step`` (as a slider in the browser rounds it)."""
    if not step or step <= 0:
        return value
    return lo + round((value - lo) / step) * step


def _representable_step(value: float, lo: float, step: float) -> float:
    """The slider step, made finer (÷2, ÷5, ÷10, ... ÷1000) until its grid holds ``value``."""
    for f in (1, 2, 5, 10, 20, 50, 100, 1000):
        if _grid_ok(value, lo, step / f):
            return step / f
    return float(step)


def _decimals(step: float) -> int:
    """Decimal places that show every value of a slider grid of this step."""
    if not step or step <= 0:
        return 3
    d = 0
    while d < 6 and abs(step * 10 ** d - round(step * 10 ** d)) > 1e-9:
        d += 1
    return d


def _same(a, b) -> bool:
    try:
        return bool(a == b) or (a != a and b != b)
    except Exception:  # noqa: BLE001 - arrays and other odd values
        return a is b


def _value_and_unit(full: str, bare: str) -> tuple[str, str]:
    """The readout's value and unit columns: a common unit goes in its own column (HTML-safe)."""
    if full.startswith(bare) and full[len(bare):].startswith(" "):
        return bare, full[len(bare) + 1:]
    return full, ""


def _numeric_failure(exc: Exception) -> bool:
    """True for numpy's floating-point errors (overflow, invalid value) raised inside a computation."""
    if isinstance(exc, (FloatingPointError, OverflowError)):
        return True
    text = str(exc)
    return isinstance(exc, RuntimeWarning) and ("overflow" in text or "invalid value" in text)


def _short(text: str) -> str:
    return text if len(text) < 90 else text[:87] + "..."


def _shown_as(name: str, value) -> str:
    """``name = value`` for a message (numbers short, text quoted)."""
    real = isinstance(value, numbers.Real) and not isinstance(value, (bool, np.bool_))
    return f"{name} = {value:g}" if real else f"{name} = {value!r}"


class Explorer:
    """Base class: a figure + controls + readout + message, updated in place.

    Subclasses implement

    * :meth:`make_controls` -> ``{name: widget}`` (initial values are the defaults),
    * :meth:`setup_axes` (limits, labels) and :meth:`make_artists` (create every
      artist once, store them on ``self``),
    * :meth:`compute` ``(values, changed) -> state``: may raise PlanargeoError,
    * :meth:`render` ``(state)``: update the artists in place and return the
      readout dictionary (it may derive overlay quantities from ``state`` and
      store them there, so that they are computed once per state),
    * optionally :meth:`adjust` ``(values, changed)``: controls that follow
      others (set with them, refused with them).

    Controls named in :attr:`display_controls` change the drawing only: a change
    of those alone re-renders the shown state without calling
    :meth:`compute` (:attr:`n_computes` counts the calls).

    Every update either shows a new state (controls, figure and readout all
    of it) or is refused as a whole (module docstring): :attr:`shown_values`
    are the control values of the state on show, equal to :attr:`values`
    whenever no callback is running.

    Parameters
    ----------
    display : {"auto", "ipympl", "image", "agg"}
        Front end (see the module docstring).
    figsize : (float, float)
        Figure size in inches.
    export_dir : str or Path, optional
        Where *Export SVG* writes (default: the current directory).
    **values
        Initial control values overriding the defaults (they also become the
        values *Reset* returns to).

    Raises
    ------
    InputError
        An unknown control or display, or an initial value the control does not
        take (:func:`check_control`).
    PlanargeoError
        The initial values describe a state that cannot be computed.
    """

    #: Title shown above the explorer.
    title: str = "Explorer"
    #: Short name used for exported file names.
    slug: str = "explorer"
    #: Figure size (inches) and resolution of the rendered image.
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
    #: Pixel radius within which a mouse press picks a handle.
    handle_radius_px: float = 12.0
    #: Simulated seconds per wall-clock second at Play speed "1×" (shown beside the speed menu when not 1).
    time_scale: float = 1.0
    #: The wall clock Play reads (seconds; a test may give the explorer its own).
    wall_clock: Callable[[], float] = staticmethod(time.monotonic)

    def __init__(self, *, display: str = "auto", figsize=None, export_dir=None, **values):
        if display not in _DISPLAYS:
            raise InputError(f"display must be one of {_DISPLAYS}, got {display!r}")
        #: True for a native explorer (:meth:`scene_picture` and :meth:`readout_of`): no figure at all
        self.native = (type(self).scene_picture is not Explorer.scene_picture
                       and type(self).readout_of is not Explorer.readout_of)
        if self.native and display in ("auto", "ipympl"):
            display = "page"
        elif display == "auto":
            display = "ipympl" if _backend_is_ipympl() else "image"
        self.display_mode = display
        self._figsize = self._figure_inches(figsize or self.figsize)
        self._figure_text = ""
        self._page_view = None
        self.export_dir = Path(export_dir) if export_dir is not None else None
        self.readout_values: dict[str, Any] = {}
        self.state: Any = None
        self.shown_values: dict[str, Any] = {}
        self.n_updates = 0
        self.n_computes = 0
        self.last_export: Path | None = None
        self._message = ""
        self._hold = 0
        self._quiet = 0
        self._pending = False
        self._changed: set[str] = set()
        self._busy = False
        self._resetting = False
        self._echo: dict[str, list] = {}
        self._shadow: dict[str, tuple[float, float]] = {}

        # controls -------------------------------------------------------------
        self.controls: dict[str, W.ValueWidget] = dict(self.make_controls())
        bad = sorted(set(self.display_controls) - set(self.controls))
        if bad:  # a programming error in the subclass, not user input
            raise InputError(f"{type(self).__name__}.display_controls names no control {bad[0]!r}")
        extra = ["key"]
        focus = list(self.focus_options())
        if focus and "focus" not in self.controls:
            self.controls["focus"] = W.Dropdown(options=["all", *focus], value="all",
                                                description="focus",
                                                layout=W.Layout(width="310px"))
            extra.append("focus")
        if "key" not in self.controls:
            self.controls["key"] = W.Checkbox(value=False, description="key (legend)", indent=False)
        self.display_controls = tuple(self.display_controls) + tuple(
            k for k in extra if k not in self.display_controls)
        self._base_focus = "focus" in extra      # the base's focus menu: its options follow the values
        unknown = sorted(set(values) - set(self.controls))
        if unknown:
            raise InputError(f"{type(self).__name__} has no control {unknown[0]!r} "
                             f"(controls: {', '.join(self.controls)})")
        for k, v in values.items():
            if k != "focus" or "focus" not in extra:
                self.controls[k].value = check_control(k, self.controls[k], v)
        if "focus" in values and "focus" in extra:  # the options of the values given, then the focus
            self.controls["focus"].options = ("all", *self.focus_options())
            self.controls["focus"].value = check_control("focus", self.controls["focus"], values["focus"])
        for w in self.controls.values():  # a value the slider's grid cannot show: a finer step
            if isinstance(w, W.FloatSlider) and w.step and not _grid_ok(w.value, w.min, w.step):
                w.step = _representable_step(w.value, w.min, w.step)
        self.defaults = {k: w.value for k, w in self.controls.items()}
        self._drag_active: Handle | None = None
        self._drag_canvas = None
        self._drag_seq = 0
        self._drag_pending: tuple[float, float] | None = None
        self._last_drag = (0.0, 0.0)
        self._extra_handles: list[Handle] = []
        self._exporting = False
        self._play_origin: dict[str, Any] | None = None
        self._last_tick = (0.0, 0.0)

        # figure (none for a native explorer: its picture is built from the state) -------------
        self.fig = self.ax = self.frames = self._msg_text = None
        if not self.native:
            self._make_artist_figure()
        self._legend = None

        # widgets ---------------------------------------------------------------
        fig_w = f"{self.figure_px[0]}px"
        self.readout = W.HTML(layout=W.Layout(width=fig_w, max_width="100%", overflow="hidden"))
        self.readout_strings: dict[str, str] = {}
        self.message_box = W.HTML(layout=W.Layout(width=fig_w, max_width="100%", height="2.8em",
                                                  min_height="2.8em", max_height="2.8em",
                                                  overflow="auto"))
        self.reset_button = W.Button(description="Reset", icon="undo",
                                     tooltip="Return every control to its default",
                                     layout=W.Layout(width="auto"))
        self.export_button = W.Button(description="SVG", icon="download",
                                      tooltip="Export the current view as SVG (a download link)",
                                      layout=W.Layout(width="auto"))
        self.export_png_button = W.Button(description="PNG", icon="download",
                                          tooltip="Export the current view as PNG (a download link)",
                                          layout=W.Layout(width="auto"))
        self.export_gif_button = W.Button(description="GIF", icon="film",
                                          tooltip="Export an animation as GIF (a download link)",
                                          layout=W.Layout(width="auto"))
        self.export_mp4_button = W.Button(description="MP4", icon="film",
                                          tooltip="Export an animation as MP4 (a download link)",
                                          layout=W.Layout(width="auto"))
        self.export_label = W.HTML(layout=W.Layout(width="310px", height="1.8em", overflow="hidden"))
        self.explain_box = W.HTML(layout=W.Layout(width=fig_w, max_width="100%"))
        self.explain_box.add_class("planargeo-explain")
        self._tooltips = {k: getattr(w, "tooltip", None) for k, w in self.controls.items()}
        self.reset_button.on_click(self.guarded(lambda _b: self.reset()))
        self.export_button.on_click(self.guarded(lambda _b: self._export_clicked("svg")))
        self.export_png_button.on_click(self.guarded(lambda _b: self._export_clicked("png")))
        self.export_gif_button.on_click(self.guarded(lambda _b: self._export_clicked("gif")))
        self.export_mp4_button.on_click(self.guarded(lambda _b: self._export_clicked("mp4")))
        self.has_play = type(self).play_step is not Explorer.play_step
        self.play_control = self.play_speed = self.play_loop = self.play_scale = None
        self._clock: _play.PlayClock | None = None
        if self.has_play:
            self.play_control = W.Play(value=0, min=0, max=10 ** 9, step=1,
                                 interval=int(round(1000 / self.play_fps)), description="play",
                                 show_repeat=False)
            self.play_speed = W.Dropdown(options=[("¼×", 0.25), ("½×", 0.5), ("1×", 1.0),
                                                  ("2×", 2.0), ("4×", 4.0)], value=1.0,
                                         description="speed", layout=W.Layout(width="150px"))
            self.play_loop = W.Checkbox(value=True, description="loop", indent=False,
                                        layout=W.Layout(width="80px"))
            scale = float(self.time_scale)
            self.play_scale = W.HTML(
                f"<span title='1× plays {scale:g} simulated seconds per second'>"
                + ("1× = real time" if scale == 1.0 else f"1× = {scale:g}× real time") + "</span>")
            self.play_speed.observe(self.guarded(lambda _c: self._restart_clock()), names="value")
            self.play_control.observe(self.guarded(self._play_tick), names="value")
            self.play_control.observe(self.guarded(self._play_toggled), names="playing")
        for name, w in self.controls.items():
            w.observe(self._make_observer(name), names="value")
        self.widget = self._layout()
        self._connect_page_play()
        if not self.native:
            self.connect_mouse()
        self._connect_handles()
        self._update(initial=True)
        self.defaults = dict(self.values)  # as first shown (controls that follow others included)

    # ---------------------------------------------------------------- subclass API
    def make_controls(self) -> dict[str, W.ValueWidget]:  # pragma: no cover - abstract
        """The explorer's controls (subclasses).

        Returns
        -------
        dict
            ``{name: widget}``; each widget's initial value is the default.

        Raises
        ------
        NotImplementedError
            In the base class.
        """
        raise NotImplementedError

    #: the initial view ``(x0, x1, y0, y1)`` of the equal-aspect axes (None: autoscale), and a light grid
    limits: tuple[float, float, float, float] | None = None
    grid: bool = True

    def setup_axes(self, ax) -> None:
        """Equal-aspect axes with :attr:`limits` and a light grid (subclasses may change).

        Parameters
        ----------
        ax : matplotlib.axes.Axes
            The explorer's axes.
        """
        setup_axes(self.limits, ax=ax, axis_off=False)
        if self.grid:
            ax.grid(True, lw=0.3, alpha=0.5)

    def make_artists(self, ax) -> None:  # pragma: no cover - abstract
        """Create every artist once and keep it on ``self`` (subclasses).

        Parameters
        ----------
        ax : matplotlib.axes.Axes
            The explorer's axes.

        Raises
        ------
        NotImplementedError
            In the base class.
        """
        raise NotImplementedError

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
            The state :meth:`render` draws.

        Raises
        ------
        PlanargeoError
            The values describe a state that cannot be shown (the update is refused).
        NotImplementedError
            In the base class.
        """
        raise NotImplementedError

    def render(self, state: Any) -> dict[str, Any]:  # pragma: no cover - abstract
        """Update the artists in place for ``state`` and return the readout (subclasses).

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

    def scene_picture(self, state: Any, view=None):
        """The picture of ``state``, built natively (optional; default None).

        An explorer that draws its state as a :class:`~planargeo.draw.picture.Picture`
        returns it here; in the page (``display="page"``) it is then drawn without any
        matplotlib artist: :meth:`readout_of` gives the numbers, and exports draw the same
        picture through matplotlib (:mod:`planargeo.draw.render`).  None: the picture is
        read off the explorer's artists.

        Parameters
        ----------
        state : Any
            What :meth:`compute` returned.
        view : (x0, x1, y0, y1), optional
            The view the user zoomed or panned to (None: the explorer's own).

        Returns
        -------
        Picture or None
        """
        return None

    def readout_of(self, state: Any) -> dict[str, Any]:
        """The readout of ``state`` without drawing (explorers with :meth:`scene_picture`).

        Parameters
        ----------
        state : Any
            What :meth:`compute` returned.

        Returns
        -------
        dict
            Readout entries, as :meth:`render` returns them.

        Raises
        ------
        NotImplementedError
            An explorer that draws only through its artists.
        """
        raise NotImplementedError(f"{type(self).__name__} has no readout_of() apart from render()")

    @property
    def native_page(self) -> bool:
        """True when this explorer draws its own picture (:attr:`native`; kept for old callers)."""
        return self.native

    def _render(self, state: Any) -> dict[str, Any]:
        """The readout of ``state``; the artists are updated unless the explorer is native."""
        return self.readout_of(state) if self.native else self.render(state)

    def adjust(self, values: dict[str, Any], changed: set[str]) -> dict[str, Any]:
        """Values of controls that follow the ``changed`` ones (default: none).

        They are set with the change and refused with it; e.g. the screw-sum
        explorer turns rotations into forces when it switches to wrenches.

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

    def extra_widgets(self) -> list:
        """Widgets shown below the controls (e.g. a Play button).

        Returns
        -------
        list
            Widgets (default: none).
        """
        return []

    def connect_mouse(self) -> None:
        """Connect extra mouse handlers (subclasses; :meth:`handles` covers dragging)."""

    def handles(self) -> list[Handle]:
        """The draggable handles of the figure (default: none).

        Returns
        -------
        list of Handle
        """
        return []

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

    def play_step(self, values: dict[str, Any], dt: float) -> dict[str, Any] | None:
        """Control values of the next Play frame after ``values``, ``dt`` seconds on (None: stop).

        An explorer that overrides this gets Play (with speed and loop) and
        animation export; the default has no Play.

        Parameters
        ----------
        values : dict
            The shown control values.
        dt : float
            Time step (seconds of the scene).

        Returns
        -------
        dict or None
        """
        return None

    def disabled(self, values: dict[str, Any]) -> dict[str, str]:
        """Controls that would change nothing in the state of ``values``, with the reason (default: none).

        After every shown update exactly these controls are disabled, each with
        its reason as tooltip; the others are enabled again.

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
        """The meaning of every symbol on screen (readout names, labels), shown in "what is shown".

        Returns
        -------
        dict
            ``{symbol or readout name: one-line meaning with its thesis equation}`` (default: none).
        """
        return {}

    def focus_options(self) -> list[str]:
        """Names of bodies or joints to focus on (default: none, no "focus" control).

        Read again after every shown update: the options may follow the values
        (e.g. the number of bodies); a focus that no longer exists falls back to "all".

        Returns
        -------
        list of str
        """
        return []

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

    # ---------------------------------------------------------------- public API

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
        """The controls', readout's and message's new values reach the page after the figure.

        The new picture is what the user waits for; the page's work on the other
        widgets (sliders, the readout table) would otherwise compete with the
        drawing of the frame for the processor.
        """
        widgets = [*self.controls.values(), self.readout, self.message_box]
        with contextlib.ExitStack() as stack:
            for w in widgets:
                stack.enter_context(w.hold_sync())
            yield

    def set(self, **values) -> "Explorer":
        """Set several controls at once (one update); returns ``self``.

        Every value is checked first (:func:`check_control`): if one is refused,
        none is set and the message names it.

        Parameters
        ----------
        **values
            ``name=value`` for each control to set.

        Returns
        -------
        Explorer
            ``self``.

        Raises
        ------
        InputError
            Never raised out of it: a bad name or value is refused and shown in :attr:`message`.
        """
        problems = []
        for k, v in values.items():
            try:
                if k not in self.controls:
                    raise InputError(f"unknown control {k!r} (controls: {', '.join(self.controls)})")
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
        """Return every control to its default (one update).

        The defaults are the values first shown, so they are taken even where a
        control's range follows another control (its range is that of the state
        reached).
        """
        self._resetting = True
        try:
            with self.hold():
                for k, v in self.defaults.items():
                    self.controls[k].value = v
                self._pending = True
        finally:
            self._resetting = False

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

    def advance(self, n_frames: int = 1, *, seconds: float | None = None,
                allow_long: bool = False) -> "Explorer":
        """Step Play ``n_frames`` frames without a front end (one update per frame).

        Each frame covers ``speed × time_scale / play_fps`` simulated seconds
        (:attr:`play_dt`), or ``seconds / n_frames`` when ``seconds`` is given,
        through :meth:`play_step` sub-steps of at most ``1 / play_fps`` seconds;
        only the frame's end is drawn (as Play does when drawing is slower than
        real time).  A None from ``play_step`` ends the run; so does a refused
        step, which keeps what was computed before it and names the reason.

        Parameters
        ----------
        n_frames : int
            Number of frames, at most :data:`~planargeo.widgets.play.MAX_ADVANCE_FRAMES`.
        seconds : float, optional
            Simulated seconds the frames cover together, at most
            :data:`~planargeo.widgets.play.MAX_ADVANCE_SECONDS`.
        allow_long : bool
            Opt in to more frames or seconds than the limits.

        Returns
        -------
        Explorer
            ``self``.

        Raises
        ------
        InputError
            The explorer has no Play (no :meth:`play_step`), ``n_frames`` is not a
            positive integer, ``seconds`` not a positive finite number, or either
            is beyond its limit without ``allow_long``.
        """
        if not self.has_play:
            raise InputError(f"{type(self).__name__} has no Play (it does not define play_step)")
        n = _play.check_count("n_frames", n_frames, _play.MAX_ADVANCE_FRAMES, allow_long)
        if seconds is None:
            per_frame = self.play_dt
            _play.check_duration("n_frames × play_dt", n * per_frame, _play.MAX_ADVANCE_SECONDS,
                                 allow_long)
        else:
            per_frame = _play.check_duration("seconds", seconds, _play.MAX_ADVANCE_SECONDS,
                                             allow_long) / n
        for _ in range(n):
            if not self._frame(per_frame):
                break
        return self

    @property
    def play_dt(self) -> float:
        """Simulated seconds per Play frame: ``speed × time_scale / play_fps``."""
        speed = self.play_speed.value if self.play_speed is not None else 1.0
        return float(speed) * float(self.time_scale) / float(self.play_fps)

    @property
    def play_max_dt(self) -> float:
        """The longest :meth:`play_step` sub-step: ``1 / play_fps`` simulated seconds."""
        return 1.0 / float(self.play_fps)

    def _frame(self, seconds: float | None = None) -> bool:
        """One shown Play frame ``seconds`` on (default :attr:`play_dt`), in sub-steps.

        False when Play ends: None from play_step, or a refused step (what was
        computed before it is shown, with the reason).
        """
        seconds = self.play_dt if seconds is None else float(seconds)
        start = dict(self.shown_values or self.values)
        vals, ended, exc = _play.run_substeps(self.play_step, start, seconds, self.play_max_dt)
        new = {k: v for k, v in vals.items() if k in self.controls and not _same(v, start.get(k))}
        before = self.n_updates
        if new:
            self.set(**new)
        shown = self.n_updates > before
        if isinstance(exc, KeyboardInterrupt):      # Ctrl-C: what was computed is shown, then it stops
            raise exc
        if exc is not None:
            message = f"play stopped: {self._reason(exc)}"
            if self.message:
                message += f"; {self.message}"
            self._refuse(message, self.figure_message(exc))
            return False
        if new and not shown:        # the new values were refused (the message says why)
            return False
        return not ended

    def _restart_clock(self) -> None:
        """Play's wall clock: started with Play (one frame due at once), its rate following the speed."""
        rate = float(self.play_speed.value) * float(self.time_scale)
        if self.play_control is None or not self.play_control.playing:
            self._clock = None
        elif self._clock is None:
            self._clock = _play.PlayClock(rate, self.wall_clock, lead=1.0 / self.play_fps)
        else:
            self._clock.rate = rate

    def _play_toggled(self, change) -> None:
        if change["new"]:
            self._play_origin = dict(self.shown_values)
        self._clock = None
        self._restart_clock()

    @property
    def _page_plays(self) -> bool:
        """True when the page's canvas paces Play (its ``playing`` trait and tick messages)."""
        canvas = getattr(self, "canvas", None)
        return canvas is not None and canvas.has_trait("playing")

    def _connect_page_play(self) -> None:
        """Play in the page: the Play button's ``playing`` is the canvas's; the canvas's ticks advance it.

        The page sends a tick as soon as the previous picture is painted; each tick covers the
        wall-clock time since the last (:class:`~planargeo.widgets.play.PlayClock`) in sub-steps
        of at most ``1 / play_fps`` s and sets one picture.  The Play widget's own timer is
        slowed to nothing: it only shows the button.
        """
        if not (self.has_play and self._page_plays):
            return
        self.canvas.on_tick = self._page_tick
        self.play_control.interval = 10 ** 7
        self._play_link = W.link((self.play_control, "playing"), (self.canvas, "playing"))

    def _page_tick(self) -> None:
        """A tick from the page while it plays: one frame of the wall-clock time since the last.

        Raises
        ------
        PlanargeoError
            Play stopped on a refused step (the message says why; the page shows it).
        """
        if not self.play_control.playing:
            return
        if self._clock is None:
            self._restart_clock()
        seconds = self._clock.due()
        if seconds <= 0 or self._frame(seconds):
            return
        if self.play_loop is not None and self.play_loop.value and self._play_origin and \
                not self._message:
            self.set(**self._play_origin)  # start again
            return
        self.play_control.playing = False
        if self._message:
            raise PlanargeoError(self._message)

    def _play_tick(self, change) -> None:
        if not self.play_control.playing or self._page_plays:
            return
        # the wall clock sets the simulated time: ticks that arrive while a slow frame was drawn
        # are dropped, and the next one covers the time they would have (display frames dropped,
        # no physics step skipped)
        interval = self.play_control.interval / 1000.0
        now = self.wall_clock()
        last_end, last_cost = self._last_tick
        if last_cost > interval and now - last_end < max(0.5 * interval, 0.01):
            return
        if self._clock is None:
            self._restart_clock()
        seconds = self._clock.due()
        if seconds <= 0:
            return
        t0 = self.wall_clock()
        ok = self._frame(seconds)
        t1 = self.wall_clock()
        self._last_tick = (t1, t1 - t0)
        if ok:
            return
        if self.play_loop is not None and self.play_loop.value and self._play_origin and \
                not self._message:
            self.set(**self._play_origin)  # start again
            return
        self.play_control.playing = False

    # ------------------------------------------------------------------- export
    def _export_path(self, path, ext: str) -> Path:
        if path is None:
            d = self.export_dir or Path.cwd()
            path = Path(d) / f"planargeo-{self.slug}-{os.getpid()}-{next(_export_counter)}.{ext}"
        try:
            path = Path(path)
            special = path.exists() and not path.is_file()
        except TypeError:
            raise InputError(f"path must be a str or os.PathLike naming a file, got {path!r}") from None
        except OSError as e:                             # e.g. a name too long for the file system
            raise OutputError(f"cannot write {path}: {e.strerror or e}") from None
        if special:
            raise OutputError(f"cannot write {path}: it exists and is not a regular file")
        return path

    def _svg_bytes(self) -> bytes:
        fig = self._picture_figure() if self.native else self.fig   # a native one: its picture
        buf = io.BytesIO()
        # no date and fixed element ids: the same view always gives the same file
        with matplotlib.rc_context({"svg.hashsalt": "planargeo"}):
            fig.savefig(buf, format="svg", metadata={"Date": None})
        return buf.getvalue()

    def _picture_figure(self):
        """The shown picture drawn by matplotlib (:func:`planargeo.draw.render.figure`), at 100 dpi."""
        from planargeo.draw.render import figure

        return figure(self.picture())

    def _png_bytes(self, dpi: float | None = None) -> bytes:
        buf = io.BytesIO()
        if self.native:   # the picture's size is the figure's in pixels: drawn at 100 dpi
            self._picture_figure().savefig(buf, format="png", dpi=100.0 * (dpi or self.dpi) / self.dpi,
                                           metadata={"Software": None})
            return buf.getvalue()
        self.fig.savefig(buf, format="png", dpi=dpi or self.dpi, metadata={"Software": None})
        return buf.getvalue()

    def export_svg(self, path=None) -> Path:
        """Write the current view to an SVG file, atomically, and return its path.

        The view is rendered to memory first and the file replaced in one step
        (:func:`planargeo.files.atomic_write`): a failure leaves an existing file
        as it was.  The file depends on the view only (no date, fixed element ids).

        Parameters
        ----------
        path : str or os.PathLike, optional
            The file; default ``planargeo-<slug>-<pid>-<n>.svg`` in ``export_dir``
            (or the current folder).

        Returns
        -------
        pathlib.Path
            The file written (absolute).

        Raises
        ------
        InputError
            ``path`` names no file.
        OutputError
            The file cannot be written (no space, no permission, a folder or a
            device such as ``/dev/full``, which is never replaced).
        """
        path = self._export_path(path, "svg")
        self.last_export = atomic_write(path, self._svg_bytes()).resolve()
        return self.last_export

    def export_png(self, path=None) -> Path:
        """Write the current view to a PNG file (at the figure's size), atomically.

        Parameters
        ----------
        path : str or os.PathLike, optional
            The file; default ``planargeo-<slug>-<pid>-<n>.png`` in ``export_dir``.

        Returns
        -------
        pathlib.Path
            The file written (absolute).

        Raises
        ------
        InputError
            ``path`` names no file.
        OutputError
            The file cannot be written.
        """
        path = self._export_path(path, "png")
        self.last_export = atomic_write(path, self._png_bytes()).resolve()
        return self.last_export

    def _frames_rgb(self, frames: int, fps: int | None = None) -> list[np.ndarray]:
        """RGB images of ``frames`` Play frames at ``fps`` in real time from the shown state (restored after)."""
        seconds = self.play_dt * self.play_fps / float(fps or self.play_fps)
        start = dict(self.shown_values)
        state, readout = self.state, dict(self.readout_values)
        out = []
        self._exporting = True
        try:
            for k in range(frames):
                if k and not self._frame(seconds):
                    break
                if self.native:
                    from matplotlib.backends.backend_agg import FigureCanvasAgg

                    canvas = FigureCanvasAgg(self._picture_figure())
                    canvas.draw()
                    out.append(np.asarray(canvas.buffer_rgba())[..., :3].copy())
                    continue
                self.fig.canvas.draw()
                out.append(np.asarray(self.fig.canvas.buffer_rgba())[..., :3].copy())
        finally:
            self._exporting = False
            self.set(**start)
            if self.values == start and self._message == "":
                self._safe_redraw()
            else:  # pragma: no cover - the start state is always showable
                self.state, self.readout_values = state, readout
        return out

    def export_animation(self, path=None, *, format: str = "gif", frames: int = 60,
                         fps: int = 20, allow_long: bool = False) -> Path:
        """Write ``frames`` Play frames from the shown state as a GIF or MP4 file, atomically.

        The file plays in real time (× Play's speed and :attr:`time_scale`): frame
        ``k`` shows the state ``k / fps`` of its seconds later.  The explorer
        returns to the shown state afterwards; stopping (Ctrl-C) writes nothing
        and leaves it there too.  GIF uses pillow; MP4 needs the ``ffmpeg``
        program (Debian's ``ffmpeg`` package).

        Parameters
        ----------
        path : str or os.PathLike, optional
            The file; default ``planargeo-<slug>-<pid>-<n>.<format>`` in ``export_dir``.
        format : {"gif", "mp4"}
            File format.
        frames : int
            Number of frames (fewer if Play ends first), at most
            :data:`~planargeo.widgets.play.MAX_ANIMATION_FRAMES`.
        fps : int
            Frames per second of the file.
        allow_long : bool
            Opt in to more frames than the limit.

        Returns
        -------
        pathlib.Path
            The file written (absolute).

        Raises
        ------
        InputError
            No Play in this explorer, an unknown format, frames / fps not positive
            integers, or more frames than the limit without ``allow_long``.
        OutputError
            The file cannot be written, or MP4 without ffmpeg.
        """
        data = self._animation_bytes(format, frames, fps, allow_long)
        path = self._export_path(path, format)
        self.last_export = atomic_write(path, data).resolve()
        return self.last_export

    def _animation_bytes(self, format: str, frames: int, fps: int, allow_long: bool = False) -> bytes:
        if format not in ("gif", "mp4"):
            raise InputError(f"format must be 'gif' or 'mp4', got {format!r}")
        frames = _play.check_count("frames", frames, _play.MAX_ANIMATION_FRAMES, allow_long)
        fps = _play.check_count("fps", fps, 1000, allow_long=None)
        if not self.has_play:
            raise InputError(f"{type(self).__name__} has no animation (it does not define play_step)")
        ffmpeg = shutil.which("ffmpeg")
        if format == "mp4" and ffmpeg is None:
            raise OutputError("mp4 export needs the ffmpeg program, which is not installed "
                              "(install Debian's ffmpeg, or use format='gif')")
        imgs = self._frames_rgb(frames, fps)
        if format == "gif":
            from PIL import Image

            pics = [Image.fromarray(a).quantize(colors=128, method=Image.Quantize.MEDIANCUT)
                    for a in imgs]
            buf = io.BytesIO()
            pics[0].save(buf, format="GIF", save_all=True, append_images=pics[1:],
                         duration=max(1, int(round(1000 / fps))), loop=0)
            return buf.getvalue()
        h, w = imgs[0].shape[:2]
        with tempfile.TemporaryDirectory() as d:
            out = Path(d) / "movie.mp4"
            cmd = [ffmpeg, "-loglevel", "error", "-y", "-f", "rawvideo", "-pix_fmt", "rgb24",
                   "-s", f"{w}x{h}", "-r", str(fps), "-i", "-",
                   "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-pix_fmt", "yuv420p",
                   "-vcodec", "libx264", str(out)]
            try:
                r = subprocess.run(cmd, input=b"".join(a.tobytes() for a in imgs),
                                   capture_output=True, timeout=300)
            except (OSError, subprocess.SubprocessError) as e:
                raise OutputError(f"ffmpeg failed: {e}") from None
            if r.returncode != 0 or not out.exists():
                raise OutputError(f"ffmpeg failed: {r.stderr.decode(errors='replace')[-300:]}")
            return out.read_bytes()

    def redraw(self) -> None:
        """Draw the figure and send it to the page.

        Only what can change is drawn (:class:`~planargeo.widgets.frames.Frames`:
        the axes' background is kept while the view stays put), and the page gets
        a light PNG (:func:`~planargeo.widgets.frames.live_png`) at once: in image
        mode as the image's value, under ipympl through its canvas, without
        ipympl's round trip through the page.
        """
        if self.display_mode == "page":
            self.canvas.picture = self.picture()
            return
        if self.native:   # image: the picture drawn by matplotlib into the image; agg: nothing to draw
            if self.display_mode == "image":
                self.image.value = self._png_bytes()
            return
        self.frames.draw()
        if self.display_mode == "ipympl":
            self.fig.canvas.blit()
        elif self.display_mode == "image":
            self.image.value = live_png(np.asarray(self.fig.canvas.buffer_rgba()))

    def picture(self) -> dict:
        """What the figure shows, as a picture's plain data (:mod:`planargeo.draw.picture`).

        Read off the explorer's artists (:func:`planargeo.draw.from_axes.picture_from_axes`),
        in the view the user zoomed or panned to in the page, if any; with the handles
        that can be dragged now and every symbol's description (:meth:`explain`).

        Returns
        -------
        dict
        """
        from planargeo.draw.from_axes import picture_from_axes

        handles = []
        for h in self.all_handles():
            try:
                where = h.where()
            except Exception:  # noqa: BLE001 - a handle that cannot say where it is: not shown
                where = None
            if where is not None:
                handles.append((h.name, where, f"drag to change {h.name}"))
        view = self._page_view
        pic = self.scene_picture(self.state, view) if self.state is not None else None
        if pic is None and self.native:
            raise PlanargeoError(f"{type(self).__name__} has no state to draw yet")
        if pic is None:
            try:
                explain = dict(self.explain())
            except Exception:  # noqa: BLE001 - descriptions are a courtesy
                explain = {}
            return picture_from_axes(self.ax, explain=explain, view=view, handles=handles).to_dict()
        for name, where, desc in handles:
            pic.handle(name, where, symbol=name, desc=desc)
        if self.controls["key"].value:
            self._add_key(pic)
        if self._figure_text:   # a refused value, said on the picture as on a figure
            (x0, x1, y0, y1) = pic.box
            pic.text("figure message", ((x0 + x1) / 2, (y0 + y1) / 2), self._figure_text, role="text",
                     color="#b00020", ha="center", va="center", z=100,
                     desc=f"refused: {self._figure_text}")
        return pic.to_dict()

    @staticmethod
    def _key_entries(pic) -> list[tuple[str, str, str]]:
        """``(symbols, meaning, colour)`` of the described elements of the picture, one per meaning."""
        groups: dict[tuple[str, str], list[str]] = {}
        for el in pic.elements:
            sym = el.get("symbol") or ""
            if not sym or el["id"] == "figure message" or el["id"].startswith("key "):
                continue
            meaning = str(el.get("desc") or "").split(":")[0].split("(")[0].strip()
            syms = groups.setdefault((meaning, el.get("color") or "#222"), [])
            if sym not in syms:
                syms.append(sym)
        return [(", ".join(syms) if len(syms) <= 2 else f"{syms[0]}…{syms[-1]}", meaning, color)
                for (meaning, color), syms in groups.items()]

    def _add_key(self, pic) -> None:
        """The key: one line per symbol of the picture, in its colour, at the upper left."""
        x0, _x1, _y0, y1 = pic.box
        for k, (sym, meaning, color) in enumerate(self._key_entries(pic)[:12]):
            text = f"{sym}: {meaning}" if meaning else sym
            pic.text(f"key {k + 1}", (x0, y1), text[:48], role="text", color=color, ha="left",
                     va="top", dx=6.0, dy=-4.0 - 14.0 * k, z=90, desc=f"key: {text}")

    def _page_drag(self, name: str, x: float, y: float) -> None:
        """A drag request from the page: one update, or a refusal the page shows."""
        if not self._drag_to(self._handle(name), x, y):
            raise PlanargeoError(self.message or f"drag of {name} refused")

    def _page_view_to(self, box) -> None:
        """The user zoomed or panned in the page (None: back to the explorer's own view)."""
        self._page_view = None if box is None else tuple(box)
        self._safe_redraw()

    def guarded(self, callback: Callable) -> Callable:
        """``callback`` for a button or the mouse: an exception becomes a message, never escapes.

        Parameters
        ----------
        callback : callable
            The function to guard.

        Returns
        -------
        callable
            A function that calls ``callback`` and shows any exception as the message.
        """
        def run(*args):
            try:
                return callback(*args)
            except Exception as exc:  # noqa: BLE001 - a callback must never raise
                self._set_message(f"internal error ({type(exc).__name__}): {exc}")

        return run

    def _repr_mimebundle_(self, **kwargs):
        """The widget view, plus a static PNG of the figure (shown where widgets are not, e.g. GitHub)."""
        bundle = self.widget._repr_mimebundle_(**kwargs)
        if isinstance(bundle, tuple):  # (data, metadata)
            data = bundle[0]
        else:
            data = bundle
        if isinstance(data, dict):
            try:
                data["image/png"] = base64.b64encode(self._png_bytes()).decode("ascii")
            except Exception:  # noqa: BLE001 - the picture is a courtesy, never an error
                pass
        return bundle

    def show(self):
        """Display the explorer (in a notebook) and return it.

        Returns
        -------
        Explorer
            ``self``.
        """
        from IPython.display import display

        display(self.widget)
        return self

    # ---------------------------------------------------------------- internals
    def _figure_inches(self, figsize) -> tuple[float, float]:
        """The figure's size in inches: at least the notebook column's width, same aspect."""
        w, h = (float(v) for v in figsize)
        min_w = EXPLORER_MIN_WIDTH_PX / self.dpi
        if w < min_w:
            w, h = min_w, h * min_w / w
        return w, h

    def _make_artist_figure(self) -> None:
        """The matplotlib figure of an explorer drawn by its artists (not native)."""
        self.fig, self.ax = self._make_figure(self._figsize)
        self.frames = Frames(self.fig)
        self.setup_axes(self.ax)
        place_labels(self.ax)  # labels avoid each other and stay inside the axes
        self.make_artists(self.ax)
        self._msg_text = self.ax.text(0.5, 0.5, "", transform=self.ax.transAxes, ha="center",
                                      va="center", fontsize=11, color="#b00020", zorder=100,
                                      wrap=True,
                                      bbox=dict(boxstyle="round", fc="white", ec="#b00020",
                                                alpha=0.9),
                                      visible=False)
        self._msg_text._planargeo_overlay = True  # a deliberate box over the figure (legibility)

    def _make_figure(self, figsize):
        w, h = figsize
        fig = Figure(figsize=(w, h), dpi=self.dpi)
        if self.display_mode == "ipympl":
            live_canvas(fig)   # draws when the explorer says so, sends light PNGs
            fig.canvas.header_visible = False
            fig.canvas.footer_visible = False
            fig.canvas.toolbar_visible = True      # its own column, never over the axes
            fig.canvas.toolbar_position = "left"
            fig.canvas.resizable = False
        else:
            from matplotlib.backends.backend_agg import FigureCanvasAgg

            FigureCanvasAgg(fig)
        ax = fig.add_subplot(1, 1, 1)
        if self.display_mode == "ipympl":
            # the toolbar's coordinate message goes to ipympl's footer, which is hidden: sending it
            # on every mouse move would only load the page and the server during a drag
            ax.format_coord = lambda x, y: ""
        ax.tick_params(labelsize=EXPLORER_TICK_PT)
        fig.subplots_adjust(left=0.09, right=0.98, bottom=0.07, top=0.97)
        return fig, ax

    @property
    def has_mp4(self) -> bool:
        """True when MP4 export works here (the ``ffmpeg`` program is installed)."""
        return shutil.which("ffmpeg") is not None

    @property
    def figure_px(self) -> tuple[int, int]:
        """Native size of the figure in pixels (as shown at 100 % zoom)."""
        w, h = self._figsize
        return int(round(w * self.dpi)), int(round(h * self.dpi))

    def _layout(self):
        wpx, _ = self.figure_px
        if self.display_mode == "ipympl":
            fig_widget = self.fig.canvas
        elif self.display_mode == "image":
            # shown at its native size (text sizes as designed), shrinking with a narrow output area
            self.image = W.Image(format="png", layout=W.Layout(width=f"{wpx}px", height="auto",
                                                               max_width="100%"))
            fig_widget = self.image
        elif self.display_mode == "page":
            self.image = None
            self.canvas = self._make_canvas()
            fig_widget = self.canvas
        else:
            self.image = None
            fig_widget = W.HTML("<i>(figure drawn off-screen)</i>")
        buttons = W.HBox([self.reset_button, W.HTML("<span style='padding:0 4px'>export</span>"),
                          self.export_button, self.export_png_button]
                         + ([self.export_gif_button] if self.has_play else [])
                         + ([self.export_mp4_button] if self.has_play and self.has_mp4 else []),
                         # the buttons keep their names: a row that does not fit wraps
                         layout=W.Layout(flex_flow="row wrap", width="330px"))
        for b in buttons.children:
            if isinstance(b, W.Button):
                b.layout.flex = "0 0 auto"
        play = ([W.HBox([self.play_control, self.play_speed, self.play_scale, self.play_loop])]
                if self.has_play else [])
        controls = W.VBox(list(self.controls.values()) + play + self.extra_widgets()
                          + [buttons, self.export_label],
                          layout=W.Layout(width="330px", min_width="330px", overflow="visible"))
        # controls on the left; on the right a reserved message line, the figure and the readout
        # under it: fixed widths and heights above the readout, so nothing moves when a message
        # appears or the readout changes (the readout only grows downwards, with nothing below)
        right = W.VBox([self.message_box, fig_widget, self.readout, self.explain_box],
                       layout=W.Layout(align_items="flex-start", overflow="visible"))
        head = W.HTML(f"<h4 style='margin:2px'>{html.escape(self.title)}</h4>")
        body = W.HBox([controls, right],
                      layout=W.Layout(flex_flow="row wrap", align_items="flex-start"))
        root = W.VBox([head, body])
        root.add_class("planargeo-explorer")
        self.readout.add_class("planargeo-readout")
        self.message_box.add_class("planargeo-message")
        fig_widget.add_class("planargeo-figure")
        return root

    # ------------------------------------------------------------------ mouse
    def _make_canvas(self):
        from planargeo.widgets.canvas import PictureCanvas

        return PictureCanvas(on_drag=self._page_drag, on_view=self._page_view_to)

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
            self._show_figure_message(_short(message))
            self._safe_redraw()

    def _make_observer(self, name: str) -> Callable:
        widget = self.controls[name]
        slider = isinstance(widget, W.FloatSlider)

        def _observer(change):
            if slider and self._screen_echo(name, widget, change):
                return
            if self._quiet:  # the explorer setting its own controls
                return
            self._changed.add(name)
            if self._hold:
                self._pending = True
                return
            self._update()

        return _observer

    #: seconds during which the browser's rounded copy of a set value counts as its echo
    ECHO_SECONDS = 2.0

    def _screen_echo(self, name: str, widget, change) -> bool:
        """True for a slider's echo: ignore it (no update, no snapping to the grid).

        A browser slider rounds a value the explorer set (a drag, a Play frame)
        to its step and sends it back; such a message (one from the front end,
        i.e. inside ipywidgets' ``set_state``) equal to the rounded copy of a
        value set in the last :attr:`ECHO_SECONDS` is not a user's change.
        """
        new, old = change["new"], change["old"]
        now = time.monotonic()
        from_front = "value" in (getattr(widget, "_property_lock", None) or {})
        recent = [r for r in self._echo.get(name, []) if now - r[0] <= self.ECHO_SECONDS]
        if from_front and isinstance(new, numbers.Real) and any(
                abs(float(new) - r[2]) <= 1e-9 * max(1.0, abs(r[2])) for r in recent):
            sh = self._shadow.get(name)
            exact = sh[0] if sh is not None and old == sh[1] else old
            self._shadow[name] = (exact, new)
            self._echo[name] = recent
            return True
        self._shadow.pop(name, None)
        if not from_front and isinstance(new, float) and math.isfinite(new) and \
                not _grid_ok(new, widget.min, widget.step):
            recent.append((now, new, _on_grid(new, widget.min, widget.step)))
            self._echo[name] = recent[-16:]
        return False

    @property
    def values(self) -> dict[str, Any]:
        """Current value of every control (a dragged value, not the slider's rounded echo of it).

        Returns
        -------
        dict
        """
        out = {}
        for k, w in self.controls.items():
            v = w.value
            sh = self._shadow.get(k)
            out[k] = sh[0] if sh is not None and v == sh[1] else v
        return out

    @contextlib.contextmanager
    def _quietly(self):
        """Set controls without triggering updates (the explorer's own changes)."""
        self._quiet += 1
        try:
            yield
        finally:
            self._quiet -= 1

    def _set_controls(self, values: dict[str, Any]) -> None:
        with self._quietly():
            for k, v in values.items():
                self.controls[k].value = v

    def _set_message(self, text: str) -> None:
        self._message = text
        if text:
            self.message_box.value = (f"<div style='color:#b00020;font-weight:bold'>"
                                      f"⚠ {html.escape(text)}</div>")
        else:
            self.message_box.value = ""

    def _show_figure_message(self, text: str) -> None:
        self._figure_text = text
        if self._msg_text is not None:
            self._msg_text.set_text(text)
            self._msg_text.set_visible(bool(text))

    @property
    def figure_text(self) -> str:
        """The message drawn on the figure or picture ("" when none is shown)."""
        return self._figure_text

    def _update(self, initial: bool = False) -> None:
        """Show the state of the controls, or refuse it; never raises after construction."""
        if self._busy:  # a re-entrant change from inside render: fold it in
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
        """Compute and render the controls' state, or refuse it (:meth:`_refuse`).

        Only display controls changed (or none: a forced update): the shown
        state is rendered again, without :meth:`compute`.
        """
        values = self.values
        try:
            for k in changed:
                if not (self._resetting and _same(values[k], self.defaults.get(k))):
                    values[k] = check_control(k, self.controls[k], values[k])
        except InputError as exc:
            if initial:
                raise
            self._refuse(str(exc), self.figure_message(exc))
            return
        rendered = False
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
                rendered = True
                readout = dict(self._render(state))
                table = self._readout_html(readout)
                message = (state.get("message", "") if isinstance(state, dict)
                           else getattr(state, "message", ""))
        except Exception as exc:  # noqa: BLE001 - refused and reported, never raised
            if initial:
                raise
            refused = ", ".join(_shown_as(k, w.value) for k, w in self.controls.items() if k in changed)
            reason = self._reason(exc)
            if _numeric_failure(exc) and refused:
                reason = (f"{refused} cannot be computed: a number left double precision's range "
                          f"({exc}); choose a smaller magnitude")
                figure = _short(reason)
            else:
                figure = self.figure_message(exc)
            self._refuse(f"{reason} (refused: {refused})" if refused else reason, figure, rendered)
            self._follow_shown()
            return
        self.state = state
        self.shown_values = self.values
        self.readout_values = readout
        self._draw_key()
        self.readout.value = table
        self._set_message(message)
        self._show_figure_message(message)
        self._follow_shown()
        self.n_updates += 1
        self._safe_redraw()

    def _focus_follow(self, values: dict[str, Any]) -> dict[str, Any]:
        """``{"focus": "all"}`` when the focus chosen no longer exists for ``values`` (else nothing)."""
        if not self._base_focus or values.get("focus", "all") == "all":
            return {}
        try:
            options = ["all", *self.focus_options()]
        except Exception:  # noqa: BLE001 - options that cannot be listed: keep the choice
            return {}
        return {} if values["focus"] in options else {"focus": "all"}

    def _follow_shown(self) -> None:
        """Focus options, disabled controls and the "what is shown" panel, for the shown state."""
        w = self.controls.get("focus")
        if self._base_focus:
            with contextlib.suppress(Exception):
                options = ("all", *self.focus_options())
                if tuple(w.options) != options:
                    value = w.value if w.value in options else "all"
                    with self._quietly():
                        w.options = options
                        w.value = value
        try:
            off = dict(self.disabled(dict(self.shown_values or self.values)))
        except Exception as exc:  # noqa: BLE001 - a faulty rule disables nothing
            off = {}
            self._message = self._message or f"internal error in disabled(): {exc}"
        if "key" not in off and not self.controls["key"].value and not self._has_key_entries():
            off["key"] = "nothing drawn now has an entry in the key"
        for k, w in self.controls.items():
            reason = off.get(k)
            if bool(w.disabled) != (reason is not None):
                w.disabled = reason is not None
            tip = str(reason) if reason is not None else self._tooltips.get(k)
            if hasattr(w, "tooltip") and w.tooltip != tip:
                w.tooltip = tip
        try:
            text = explain_html(dict(self.explain()))
        except Exception as exc:  # noqa: BLE001
            text = f"<i>no explanation: {html.escape(str(exc))}</i>"
        if self.explain_box.value != text:
            self.explain_box.value = text

    def _has_key_entries(self) -> bool:
        """True when something drawn now has an entry in the key (a native picture: its symbols)."""
        return self.state is not None if self.native else has_legend_entries(self.ax)

    @staticmethod
    def _reason(exc: Exception) -> str:
        if isinstance(exc, PlanargeoError):
            return str(exc)
        if isinstance(exc, (ArithmeticError, RuntimeWarning, np.linalg.LinAlgError, ValueError)):
            return f"cannot compute this configuration: {exc}"
        return f"internal error ({type(exc).__name__}): {exc}"

    def _refuse(self, message: str, figure_text: str | None = None, rerender: bool = False) -> None:
        """Report ``message`` and return controls, figure and readout to the shown state."""
        reverted = [k for k, v in self.shown_values.items()
                    if k in self.controls and not _same(self.controls[k].value, v)]
        self._set_controls(self.shown_values)
        for k in reverted:  # tell the browser even while it is sending this very control
            with contextlib.suppress(Exception):
                self.controls[k].send_state("value")
        self._changed.clear()
        self._pending = False
        if rerender:  # a render that failed midway may have moved some artists
            try:
                self._render(self.state)
            except Exception as exc:  # noqa: BLE001
                message += f"; redrawing the shown state failed ({type(exc).__name__}): {exc}"
        self._set_message(message)
        self._show_figure_message(_short(message) if figure_text is None else figure_text)
        self._safe_redraw()

    def figure_message(self, exc: Exception) -> str:
        """Short text drawn on the figure when an update is refused.

        Parameters
        ----------
        exc : Exception
            Why the update was refused.

        Returns
        -------
        str
        """
        return _short(self._reason(exc))

    def _safe_redraw(self) -> None:
        if self._exporting:  # frames of an animation are drawn by the exporter
            return
        try:
            self.redraw()
        except Exception as exc:  # noqa: BLE001
            self._message = self._message or f"drawing failed ({type(exc).__name__}): {exc}"

    def _readout_html(self, values: dict[str, Any]) -> str:
        zero = float(self.zero_tol) * float(self.scale)
        self.readout_strings = {}
        rows = []
        for k, v in values.items():
            if str(k).startswith("_"):
                continue
            full = value_text(v, self.units.get(k, ""), zero=zero)
            self.readout_strings[str(k)] = html.unescape(full)
            text, unit = _value_and_unit(full, fmt(v, zero=zero))
            rows.append(
                f"<tr><td style='padding-right:6px;line-height:1.25;white-space:nowrap;"
                f"overflow:hidden;text-overflow:ellipsis;max-width:300px' title='{html.escape(str(k))}'>"
                f"{html.escape(str(k))}</td>"
                f"<td style='text-align:right;font-family:monospace;line-height:1.25;"
                f"white-space:nowrap'>{text}</td>"
                f"<td style='padding-left:3px;line-height:1.25;white-space:nowrap;color:#555'>"
                f"{unit}</td></tr>")
        return (f"<b>Readout</b><table class='planargeo-readout' style='font-size:12px;"
                f"table-layout:auto;border-collapse:collapse'>{''.join(rows)}</table>")

    def _export_bytes(self, kind: str) -> bytes:
        if kind == "svg":
            return self._svg_bytes()
        if kind == "png":
            return self._png_bytes()
        return self._animation_bytes(kind, 60, self.play_fps)

    def _export_clicked(self, kind: str = "svg") -> None:
        """Export button: a download link in the page (and the file in ``export_dir`` if set)."""
        mime = {"svg": "image/svg+xml", "png": "image/png", "gif": "image/gif",
                "mp4": "video/mp4"}[kind]
        try:
            if self.export_dir is not None:
                p = {"svg": self.export_svg, "png": self.export_png}.get(
                    kind, lambda: self.export_animation(format=kind, fps=self.play_fps))()
                data, name = p.read_bytes(), p.name
                saved = f"saved <code>{html.escape(str(p))}</code> "
            else:
                data, name, saved = self._export_bytes(kind), f"planargeo-{self.slug}.{kind}", ""
            href = f"data:{mime};base64,{base64.b64encode(data).decode('ascii')}"
            self.export_label.value = (
                f"<div style='white-space:nowrap;overflow:hidden;text-overflow:ellipsis'>"
                f"<a download='{html.escape(name)}' href='{href}' class='planargeo-download' "
                f"style='font-weight:bold'>⬇ {html.escape(name)}</a> {saved}</div>")
        except Exception as exc:  # noqa: BLE001
            self.export_label.value = (f"<span style='color:#b00020'>export failed: "
                                       f"{html.escape(str(exc))}</span>")

    def _draw_key(self) -> None:
        """The legend of labelled artists when the "key" control is on (removed when off).

        A native explorer's key is part of its picture (:meth:`picture`)."""
        if self.native:
            return
        if self._legend is not None:
            with contextlib.suppress(Exception):
                self._legend.remove()
            self._legend = None
        if not self.controls["key"].value:
            return
        from planargeo.draw.artists import legend_handles

        handles = legend_handles(self.ax)
        if handles:
            self._legend = self.ax.legend(handles=handles, loc="upper left", fontsize=LABEL_PT,
                                          framealpha=0.9, handlelength=1.6, borderaxespad=0.3)
            self._legend.set_zorder(50)

    # -------------------------------------------------------------- benchmarking
    def time_update(self, name: str, values: list, repeat: int = 1) -> list[float]:
        """Seconds from setting ``controls[name]`` to the redrawn figure, per value.

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
            Seconds per update.
        """
        out = []
        for _ in range(repeat):
            for v in values:
                t0 = time.perf_counter()
                self.controls[name].value = v
                out.append(time.perf_counter() - t0)
        return out
