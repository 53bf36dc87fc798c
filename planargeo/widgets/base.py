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
    no display at all (tests, benchmarks): the figure is drawn on an Agg canvas.

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

Examples
--------
Two equal and opposite rotations add up to a translation (thesis 4.2); a zero
rotation is refused with a message, not an exception:

>>> from planargeo.widgets import ScrewSumExplorer
>>> ex = ScrewSumExplorer(display="agg")
>>> ex.controls["size2"].value = -1.0
>>> ex.readout_values["case"], ex.readout_values["pole of sum"]
('opposite_rotations', 'at infinity')
>>> ex.controls["size2"].value = 0.0
>>> ex.message
'v2 must be non-zero, got array([ 0., -0.,  0.]) (refused: size2 = 0)'
>>> ex.controls["size2"].value, ex.readout_values["case"]    # back to the shown state
(-1.0, 'opposite_rotations')
"""
from __future__ import annotations

import contextlib
import html
import io
import itertools
import numbers
import os
import time
import warnings
from pathlib import Path
from typing import Any, Callable

import ipywidgets as W
import matplotlib
import numpy as np
from matplotlib.figure import Figure
from traitlets import validate

from planargeo.draw.style import setup_axes
from planargeo.errors import InputError, OutputError, PlanargeoError
from planargeo.files import atomic_write

__all__ = ["Explorer", "Step", "cached", "check_control", "fmt"]

_DISPLAYS = ("auto", "ipympl", "image", "agg")
_export_counter = itertools.count(1)


def fmt(x: Any, digits: int = 4) -> str:
    """Readable text for a readout value (numbers rounded, ideal values named).

    Examples
    --------
    >>> fmt(0.123456), fmt(float("inf")), fmt((1.0, -2.5)), fmt(True)
    ('0.1235', '∞', '(1, -2.5)', 'yes')
    """
    if isinstance(x, (bool, np.bool_)):
        return "yes" if x else "no"
    if isinstance(x, (int, np.integer)):
        return str(int(x))
    if isinstance(x, (float, np.floating)):
        if not np.isfinite(x):
            return "∞" if x > 0 else ("−∞" if x < 0 else "—")
        if x == 0:
            return "0"
        if abs(x) >= 1e5 or abs(x) < 1e-3:
            return f"{x:.{digits - 1}e}"
        return f"{x:.{digits}g}"
    if isinstance(x, (tuple, list, np.ndarray)):
        a = np.ravel(np.asarray(x, dtype=object))
        try:  # components at rounding level relative to the largest are shown as 0
            f = np.asarray(a, dtype=float)
            big = np.max(np.abs(f[np.isfinite(f)]), initial=0.0)
            a = np.where(np.isfinite(f) & (np.abs(f) <= 1e-12 * big), 0.0, f)
        except (TypeError, ValueError):
            pass
        return "(" + ", ".join(fmt(v, digits) for v in a) + ")"
    return html.escape(str(x))


#: entries an explorer's per-parameter cache holds before it is emptied
CACHE_LIMIT = 32


def cached(cache: dict, key, make: Callable[[], Any]) -> Any:
    """``cache[key]``, built by ``make()`` when missing; a full cache (> :data:`CACHE_LIMIT`) is emptied.

    Explorers keep models or integrated shapes per parameter tuple with this, so
    a slider sweep over many values cannot grow a cache without bound.

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
    """A slider description: ``Step(lo, hi, step, value, label, integer=False)``."""

    def __init__(self, lo: float, hi: float, step: float, value: float, label: str = "",
                 integer: bool = False):
        self.lo, self.hi, self.step, self.value, self.label = lo, hi, step, value, label
        self.integer = integer

    def make(self, name: str) -> FloatSlider | IntSlider:
        cls, shown = (IntSlider, "d") if self.integer else (FloatSlider, ".3g")
        return cls(value=self.value, min=self.lo, max=self.hi, step=self.step,
                   description=self.label or name, continuous_update=True, readout_format=shown,
                   style={"description_width": "initial"}, layout=W.Layout(width="310px"))


_SELECTIONS = (W.Dropdown, W.ToggleButtons, W.RadioButtons, W.Select)


def check_control(name: str, widget, value):
    """``value`` as control ``name`` holds it, or :class:`InputError` naming the control.

    A slider takes a finite real number in its range (an integer slider an
    integral one), a list (dropdown, toggle buttons) one of its options, a
    checkbox ``True`` or ``False``, a text box a string.

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
    if isinstance(widget, W.Text) and not isinstance(value, str):
        raise InputError(f"{name} must be text, got {value!r}")
    return value


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
    dpi: int = 90
    #: Controls that only change what is drawn (no recompute when only they change).
    display_controls: tuple[str, ...] = ()

    def __init__(self, *, display: str = "auto", figsize=None, export_dir=None, **values):
        if display not in _DISPLAYS:
            raise InputError(f"display must be one of {_DISPLAYS}, got {display!r}")
        if display == "auto":
            display = "ipympl" if _backend_is_ipympl() else "image"
        self.display_mode = display
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

        # controls -------------------------------------------------------------
        self.controls: dict[str, W.ValueWidget] = dict(self.make_controls())
        bad = sorted(set(self.display_controls) - set(self.controls))
        if bad:  # a programming error in the subclass, not user input
            raise InputError(f"{type(self).__name__}.display_controls names no control {bad[0]!r}")
        unknown = sorted(set(values) - set(self.controls))
        if unknown:
            raise InputError(f"{type(self).__name__} has no control {unknown[0]!r} "
                             f"(controls: {', '.join(self.controls)})")
        for k, v in values.items():
            self.controls[k].value = check_control(k, self.controls[k], v)
        self.defaults = {k: w.value for k, w in self.controls.items()}

        # figure ----------------------------------------------------------------
        self.fig, self.ax = self._make_figure(figsize or self.figsize)
        self.setup_axes(self.ax)
        self.make_artists(self.ax)
        self._msg_text = self.ax.text(0.5, 0.5, "", transform=self.ax.transAxes, ha="center",
                                      va="center", fontsize=11, color="#b00020", zorder=100,
                                      wrap=True,
                                      bbox=dict(boxstyle="round", fc="white", ec="#b00020",
                                                alpha=0.9),
                                      visible=False)

        # widgets ---------------------------------------------------------------
        self.readout = W.HTML(layout=W.Layout(width="230px"))
        self.message_box = W.HTML(layout=W.Layout(min_height="1.5em"))
        self.reset_button = W.Button(description="Reset", icon="undo",
                                     tooltip="Return every control to its default")
        self.export_button = W.Button(description="Export SVG", icon="download",
                                      tooltip="Write the current view to an SVG file")
        self.export_label = W.HTML()
        self.reset_button.on_click(self.guarded(lambda _b: self.reset()))
        self.export_button.on_click(self.guarded(lambda _b: self._export_clicked()))
        for name, w in self.controls.items():
            w.observe(self._make_observer(name), names="value")
        self.widget = self._layout()
        self.connect_mouse()
        self._update(initial=True)

    # ---------------------------------------------------------------- subclass API
    def make_controls(self) -> dict[str, W.ValueWidget]:  # pragma: no cover - abstract
        raise NotImplementedError

    #: the initial view ``(x0, x1, y0, y1)`` of the equal-aspect axes (None: autoscale), and a light grid
    limits: tuple[float, float, float, float] | None = None
    grid: bool = True

    def setup_axes(self, ax) -> None:
        setup_axes(ax, self.limits, axis_off=False)
        if self.grid:
            ax.grid(True, lw=0.3, alpha=0.5)

    def make_artists(self, ax) -> None:  # pragma: no cover - abstract
        raise NotImplementedError

    def compute(self, values: dict[str, Any], changed: set[str]) -> Any:  # pragma: no cover
        raise NotImplementedError

    def render(self, state: Any) -> dict[str, Any]:  # pragma: no cover - abstract
        raise NotImplementedError

    def adjust(self, values: dict[str, Any], changed: set[str]) -> dict[str, Any]:
        """Values of controls that follow the ``changed`` ones (default: none).

        They are set with the change and refused with it; e.g. the screw-sum
        explorer turns rotations into forces when it switches to wrenches.
        """
        return {}

    def extra_widgets(self) -> list:
        """Widgets shown below the controls (e.g. a Play button)."""
        return []

    def connect_mouse(self) -> None:
        """Connect mouse handlers (subclasses; only useful under ipympl)."""

    def connect_drag(self, x_control: str, y_control: str, target: Callable[[], Any],
                     radius_px: float = 12.0) -> None:
        """Let the mouse drag the point ``target()`` (data ``(x, y)``) on the figure.

        A press within ``radius_px`` pixels of the point starts a drag; motion
        sets the two controls (clamped to their ranges, one update per move);
        release ends it.  Works wherever the canvas emits mouse events
        (``%matplotlib widget``); harmless elsewhere.
        """
        state = {"on": False}

        def press(ev):
            if ev.inaxes is not self.ax or ev.button not in (1, None):
                return
            xy = target()
            if xy is None or not np.all(np.isfinite(xy)):
                return
            px = self.ax.transData.transform(np.asarray(xy, float))
            state["on"] = bool(np.hypot(px[0] - ev.x, px[1] - ev.y) <= radius_px)

        def move(ev):
            if not state["on"] or ev.inaxes is not self.ax or ev.xdata is None:
                return
            cx, cy = self.controls[x_control], self.controls[y_control]
            x = float(np.clip(ev.xdata, cx.min, cx.max))
            y = float(np.clip(ev.ydata, cy.min, cy.max))
            self.set(**{x_control: x, y_control: y})

        def release(ev):
            state["on"] = False

        self._drag_state = state
        cids = getattr(self, "_mouse_cids", [])
        cids += [self.fig.canvas.mpl_connect(event, self.guarded(fn)) for event, fn in
                 (("button_press_event", press), ("motion_notify_event", move),
                  ("button_release_event", release))]
        self._mouse_cids = cids

    # ---------------------------------------------------------------- public API
    @property
    def values(self) -> dict[str, Any]:
        """Current value of every control."""
        return {k: w.value for k, w in self.controls.items()}

    @property
    def message(self) -> str:
        """The message shown ("" when the last update succeeded)."""
        return self._message

    @contextlib.contextmanager
    def hold(self):
        """Change several controls with a single update at the end."""
        self._hold += 1
        try:
            yield self
        finally:
            self._hold -= 1
            if self._hold == 0 and self._pending:
                self._pending = False
                self._update()

    def set(self, **values) -> "Explorer":
        """Set several controls at once (one update); returns ``self``.

        Every value is checked first (:func:`check_control`): if one is refused,
        none is set and the message names it.
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
        """Return every control to its default (one update)."""
        with self.hold():
            for k, v in self.defaults.items():
                self.controls[k].value = v
            self._pending = True

    def export_svg(self, path=None) -> Path:
        """Write the current view to an SVG file, atomically, and return its path.

        The view is rendered to memory first and the file replaced in one step
        (:func:`planargeo.files.atomic_write`): a failure leaves an existing file
        as it was.  The file depends on the view only (no date, fixed element ids).

        Raises
        ------
        OutputError
            The file cannot be written (no space, no permission, a folder or a
            device such as ``/dev/full``, which is never replaced).
        """
        if path is None:
            d = self.export_dir or Path.cwd()
            path = Path(d) / f"planargeo-{self.slug}-{os.getpid()}-{next(_export_counter)}.svg"
        try:
            path = Path(path)
            special = path.exists() and not path.is_file()
        except TypeError:
            raise InputError(f"path must be a str or os.PathLike naming a file, got {path!r}") from None
        except OSError as e:                             # e.g. a name too long for the file system
            raise OutputError(f"cannot write {path}: {e.strerror or e}") from None
        if special:
            raise OutputError(f"cannot write {path}: it exists and is not a regular file")
        buf = io.BytesIO()
        # no date and fixed element ids: the same view always gives the same file
        with matplotlib.rc_context({"svg.hashsalt": "planargeo"}):
            self.fig.savefig(buf, format="svg", metadata={"Date": None})
        self.last_export = atomic_write(path, buf.getvalue()).resolve()
        return self.last_export

    def redraw(self) -> None:
        """Draw the figure and refresh the front end."""
        if self.display_mode == "ipympl":
            self.fig.canvas.draw_idle()
        elif self.display_mode == "agg":
            self.fig.canvas.draw()
        else:
            buf = io.BytesIO()
            self.fig.savefig(buf, format="png", dpi=self.dpi)
            self.image.value = buf.getvalue()

    def guarded(self, callback: Callable) -> Callable:
        """``callback`` for a button or the mouse: an exception becomes a message, never escapes."""
        def run(*args):
            try:
                return callback(*args)
            except Exception as exc:  # noqa: BLE001 - a callback must never raise
                self._set_message(f"internal error ({type(exc).__name__}): {exc}")

        return run

    def _repr_mimebundle_(self, **kwargs):
        return self.widget._repr_mimebundle_(**kwargs)

    def show(self):
        """Display the explorer (in a notebook) and return it."""
        from IPython.display import display

        display(self.widget)
        return self

    # ---------------------------------------------------------------- internals
    def _make_figure(self, figsize):
        if self.display_mode == "ipympl":
            import matplotlib.pyplot as plt

            with plt.ioff():
                fig = plt.figure(figsize=figsize, dpi=self.dpi)
            fig.canvas.header_visible = False
            fig.canvas.footer_visible = False
            fig.canvas.toolbar_position = "bottom"
            fig.canvas.resizable = False
        else:
            from matplotlib.backends.backend_agg import FigureCanvasAgg

            fig = Figure(figsize=figsize, dpi=self.dpi)
            FigureCanvasAgg(fig)
        ax = fig.add_subplot(1, 1, 1)
        fig.subplots_adjust(left=0.08, right=0.98, bottom=0.07, top=0.95)
        return fig, ax

    def _layout(self):
        if self.display_mode == "ipympl":
            fig_widget = self.fig.canvas
        elif self.display_mode == "image":
            self.image = W.Image(format="png", layout=W.Layout(width="400px", height="auto"))
            fig_widget = self.image
        else:
            self.image = None
            fig_widget = W.HTML("<i>(figure drawn off-screen)</i>")
        buttons = W.HBox([self.reset_button, self.export_button])
        controls = W.VBox(list(self.controls.values()) + self.extra_widgets() + [buttons,
                                                                                self.export_label],
                          layout=W.Layout(min_width="320px", overflow="visible"))
        right = W.VBox([W.HTML("<b>Readout</b>"), self.readout, self.message_box])
        head = W.HTML(f"<h4 style='margin:2px'>{html.escape(self.title)}</h4>")
        body = W.HBox([controls, fig_widget, right],
                      layout=W.Layout(flex_flow="row wrap", align_items="flex-start"))
        root = W.VBox([head, body])
        root.add_class("planargeo-explorer")
        self.readout.add_class("planargeo-readout")
        fig_widget.add_class("planargeo-figure")
        return root

    def _make_observer(self, name: str) -> Callable:
        def _observer(change):
            if self._quiet:  # the explorer setting its own controls
                return
            self._changed.add(name)
            if self._hold:
                self._pending = True
                return
            self._update()

        return _observer

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
        self._msg_text.set_text(text)
        self._msg_text.set_visible(bool(text))

    def _update(self, initial: bool = False) -> None:
        """Show the state of the controls, or refuse it; never raises after construction."""
        if self._busy:  # a re-entrant change from inside render: fold it in
            self._pending = True
            return
        self._busy = True
        changed = set(self.controls) if initial else set(self._changed)
        self._changed.clear()
        try:
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
            with warnings.catch_warnings():
                warnings.simplefilter("error", RuntimeWarning)
                if changed <= set(self.display_controls) and not initial:
                    state = self.state
                else:
                    self.n_computes += 1
                    state = self.compute(values, changed | set(follow))
                rendered = True
                readout = dict(self.render(state))
                table = self._readout_html(readout)
                message = (state.get("message", "") if isinstance(state, dict)
                           else getattr(state, "message", ""))
        except Exception as exc:  # noqa: BLE001 - refused and reported, never raised
            if initial:
                raise
            refused = ", ".join(_shown_as(k, w.value) for k, w in self.controls.items() if k in changed)
            self._refuse(f"{self._reason(exc)} (refused: {refused})" if refused else self._reason(exc),
                         self.figure_message(exc), rendered)
            return
        self.state = state
        self.shown_values = self.values
        self.readout_values = readout
        self.readout.value = table
        self._set_message(message)
        self._show_figure_message(message)
        self.n_updates += 1
        self._safe_redraw()

    @staticmethod
    def _reason(exc: Exception) -> str:
        if isinstance(exc, PlanargeoError):
            return str(exc)
        if isinstance(exc, (ArithmeticError, RuntimeWarning, np.linalg.LinAlgError, ValueError)):
            return f"cannot compute this configuration: {exc}"
        return f"internal error ({type(exc).__name__}): {exc}"

    def _refuse(self, message: str, figure_text: str | None = None, rerender: bool = False) -> None:
        """Report ``message`` and return controls, figure and readout to the shown state."""
        self._set_controls(self.shown_values)
        self._changed.clear()
        self._pending = False
        if rerender:  # a render that failed midway may have moved some artists
            try:
                self.render(self.state)
            except Exception as exc:  # noqa: BLE001
                message += f"; redrawing the shown state failed ({type(exc).__name__}): {exc}"
        self._set_message(message)
        self._show_figure_message(_short(message) if figure_text is None else figure_text)
        self._safe_redraw()

    def figure_message(self, exc: Exception) -> str:
        """Short text drawn on the figure when an update is refused."""
        return _short(self._reason(exc))

    def _safe_redraw(self) -> None:
        try:
            self.redraw()
        except Exception as exc:  # noqa: BLE001
            self._message = self._message or f"drawing failed ({type(exc).__name__}): {exc}"

    def _readout_html(self, values: dict[str, Any]) -> str:
        rows = "".join(
            f"<tr><td style='padding-right:6px;line-height:1.2'>{html.escape(str(k))}</td>"
            f"<td style='text-align:right;font-family:monospace;line-height:1.2'>{fmt(v)}</td></tr>"
            for k, v in values.items() if not str(k).startswith("_"))
        return f"<table class='planargeo-readout' style='font-size:12px'>{rows}</table>"

    def _export_clicked(self) -> None:
        try:
            p = self.export_svg()
            self.export_label.value = f"saved <code>{html.escape(str(p))}</code>"
        except Exception as exc:  # noqa: BLE001
            self.export_label.value = (f"<span style='color:#b00020'>export failed: "
                                       f"{html.escape(str(exc))}</span>")

    # -------------------------------------------------------------- benchmarking
    def time_update(self, name: str, values: list, repeat: int = 1) -> list[float]:
        """Seconds from setting ``controls[name]`` to the redrawn figure, per value."""
        out = []
        for _ in range(repeat):
            for v in values:
                t0 = time.perf_counter()
                self.controls[name].value = v
                out.append(time.perf_counter() - t0)
        return out
