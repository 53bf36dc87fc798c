"""Controls as data (:class:`Step`, :class:`Choice`, :class:`Toggle`) and :func:`check_control`, the
one rule for what a control takes.  Sliders keep a value outside their range, so that the
explorer refuses it by name instead of the browser moving it to an end.

Examples
--------
>>> Step(0.0, 2.0, 0.5, 1.0, "length").make("length").value
1.0
>>> Choice(("revolute", "prismatic"), "prismatic", "joints").make("joints").value
'prismatic'
>>> check_control("links", Step(1, 20, 1, 3, integer=True).make("links"), 2.5)
Traceback (most recent call last):
...
planargeo.errors.InputError: links must be an integer between 1 and 20, got 2.5
"""
from __future__ import annotations

import contextlib
import html
import math
import numbers
import re
import time
from typing import Any, Callable

import ipywidgets as W
import numpy as np
import traitlets
from traitlets import validate

from planargeo.errors import InputError
from planargeo.widgets.readout import power_text

#: a symbol with combining marks above it (ψ̇, q̈)
_MARKED = re.compile(r"(\S[\u0300-\u036f]+)")


def marks_bold(text: str) -> str:
    """HTML ``text`` with each symbol that carries a combining mark (ψ̇, q̈) in bold.

    At the page's 11-13 px the fonts here draw a combining dot as one grey pixel ("ψ̈" reads
    "ψ"); bold draws it 2 × 2 px.

    Parameters
    ----------
    text : str
        HTML (already escaped).

    Returns
    -------
    str

    Examples
    --------
    >>> marks_bold("ψ̈ crank")
    '<b>ψ̈</b> crank'
    """
    return _MARKED.sub(r"<b>\1</b>", text)

__all__ = ["CACHE_LIMIT", "TEXT_LIMIT", "cached", "Step", "Choice", "Toggle",
           "make_control", "check_control", "widen", "number_text", "ControlsMixin"]


#: entries an explorer's per-parameter cache holds before it is emptied
CACHE_LIMIT = 32


def cached(cache: dict, key, make: Callable[[], Any]) -> Any:
    """``cache[key]``, built by ``make()`` when missing; a full cache (> :data:`CACHE_LIMIT`) is emptied.

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
        The entry, whether built now or by an earlier call.

    Examples
    --------
    >>> store = {}
    >>> cached(store, (1.0, 2.0), lambda: "model"), cached(store, (1.0, 2.0), lambda: "other")
    ('model', 'model')
    """
    if key not in cache:
        if len(cache) > CACHE_LIMIT:
            cache.clear()
        cache[key] = make()
    return cache[key]


#: a slider's state the page's slider applies only in a change of the model it did not touch itself
VIEW_KEYS = ("disabled", "orientation", "readout")


class _PageSlider:
    """A slider whose ``disabled`` (``readout``, ``orientation``) reaches the page in a message of its
    own, after the value.

    The page's slider (ipywidgets 8.1) applies ``disabled`` in its ``update``, which it skips for a
    change it made itself.  Set to a new value, it writes back its copy of the value rounded to its
    grid (60 came back as 59.99999999999997 on a step of 5 from −180), within the change that brought
    the value; Backbone then reports that whole change as the slider's own, and a ``disabled`` sent
    with the value is kept in the model but never drawn: the slider stays greyed (or live) as before.
    Sent alone, no value is set and nothing is skipped.
    """

    def send_state(self, key=None):
        keys = list(self.keys if key is None else [key] if isinstance(key, str) else key)
        view = [k for k in keys if k in VIEW_KEYS]
        if not view or len(view) == len(keys):
            return super().send_state(keys)
        super().send_state([k for k in keys if k not in VIEW_KEYS])
        return super().send_state(view)


class FloatSlider(_PageSlider, W.FloatSlider):
    """A float slider that keeps a value outside its range, for the explorer to refuse by name.

    A value the page sets is not echoed back to it (``echo_update=False``): the page shows it.
    Its ``disabled`` goes to the page in a message of its own (:class:`_PageSlider`).
    """

    value = traitlets.CFloat(0.0, help="Float value").tag(sync=True, echo_update=False)

    @validate("value")
    def _validate_value(self, proposal):
        return proposal["value"]


class IntSlider(_PageSlider, W.IntSlider):
    """An integer slider that keeps a value outside its range (see :class:`FloatSlider`)."""

    value = traitlets.CInt(0, help="Int value").tag(sync=True, echo_update=False)

    @validate("value")
    def _validate_value(self, proposal):
        return proposal["value"]


class _Control:
    """A control's description: :meth:`make` builds its widget."""

    def make(self, name: str) -> W.ValueWidget:
        """The control's widget.

        Parameters
        ----------
        name : str
            Description used when the control has no label.

        Returns
        -------
        ipywidgets.ValueWidget
        """
        raise NotImplementedError


class Step(_Control):
    """A slider description.

    Parameters
    ----------
    lo, hi : float
        Range of the slider.
    step : float
        Slider step (made finer when ``value`` is not on its grid).
    value : float
        Default value.
    label : str
        Description shown beside the slider (default: the control's name): short, a symbol and unit.
    integer : bool
        An integer slider.
    tip : str
        What the slider means, shown on hover (default: none).
    """

    def __init__(self, lo: float, hi: float, step: float, value: float, label: str = "",
                 integer: bool = False, tip: str = ""):
        self.lo, self.hi, self.step, self.value, self.label = lo, hi, step, value, label
        self.integer, self.tip = integer, tip

    def make(self, name: str) -> FloatSlider | IntSlider:
        # a default off the grid makes the step finer: it must be shown exactly
        step = self.step if self.integer else _representable_step(self.value, self.lo, self.step)
        cls, shown = (IntSlider, "d") if self.integer else (FloatSlider, f".{_decimals(step)}f")
        w = cls(value=self.value, min=self.lo, max=self.hi, step=step,
                description=self.label or name, continuous_update=True, readout_format=shown,
                style={"description_width": "initial"}, layout=W.Layout(width="310px"))
        if _MARKED.search(w.description):       # ψ̇: its dot drawn bold, else one grey pixel at 12 px
            w.description_allow_html, w.description = True, marks_bold(html.escape(w.description))
        if self.tip:
            w.tooltip = self.tip
        return w


class Choice(_Control):
    """A list description.

    Parameters
    ----------
    options : sequence
        The options (values, or ``(label, value)`` pairs).
    value : Any
        Default option.
    label : str
        Description shown beside the list.
    buttons : bool
        Toggle buttons instead of a dropdown menu.
    """

    def __init__(self, options, value, label: str = "", buttons: bool = False):
        self.options, self.value, self.label, self.buttons = tuple(options), value, label, buttons

    def make(self, name: str) -> W.Dropdown | W.ToggleButtons:
        cls = W.ToggleButtons if self.buttons else W.Dropdown
        return cls(options=self.options, value=self.value, description=self.label or name,
                   style={"description_width": "initial"},
                   layout=W.Layout(width="auto" if self.buttons else "310px"))


class Toggle(_Control):
    """A checkbox description.

    Parameters
    ----------
    value : bool
        Default.
    label : str
        Description shown beside the box.
    """

    def __init__(self, value: bool = False, label: str = ""):
        self.value, self.label = bool(value), label

    def make(self, name: str) -> W.Checkbox:
        return W.Checkbox(value=self.value, description=self.label or name, indent=False)


def make_control(name: str, spec):
    """The widget of a control: ``spec.make(name)`` for a description, the widget itself otherwise.

    Parameters
    ----------
    name : str
        The control's name.
    spec : Step, Choice, Toggle or ipywidgets.ValueWidget
        The control's description or widget.

    Returns
    -------
    ipywidgets.ValueWidget

    Examples
    --------
    >>> make_control("show", Toggle(True)).value
    True
    """
    return spec.make(name) if isinstance(spec, _Control) else spec


_SELECTIONS = (W.Dropdown, W.ToggleButtons, W.RadioButtons, W.Select)


def widen(slider, top) -> None:
    """Widen ``slider``'s range to ``top`` and send the new range to the page at once, in a message of its own.

    The page may apply one message's value before its range: a value beyond the range it still held
    would be pulled back to that range's end (and the rest of the message, e.g. ``disabled``, not
    shown).  Sent ahead, the wider range is there when the value arrives.

    Parameters
    ----------
    slider : ipywidgets IntSlider or FloatSlider
    top : number
        The new ``max``.

    Examples
    --------
    >>> s = W.IntSlider(value=0, min=0, max=0)
    >>> widen(s, 7); s.max
    7
    """
    slider.max = top
    slider.send_state("max")


def check_control(name: str, widget, value):
    """``value`` as control ``name`` holds it, or :class:`InputError` naming the control.

    A slider takes a finite number in its range, a list one of its options, a checkbox a bool,
    a text box a string whose numbers are finite and at most :data:`TEXT_LIMIT` in magnitude.

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
        The value as the control holds it (float or int for a slider).

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
    >>> check_control("joint speeds", W.Text(), "1, 1e150")
    Traceback (most recent call last):
    ...
    planargeo.errors.InputError: joint speeds: numbers typed here must lie between -1 000 000 and 1 000 000, got 1e150
    """
    if isinstance(widget, (W.FloatSlider, W.IntSlider)):
        integer = isinstance(widget, W.IntSlider)
        real = isinstance(value, numbers.Real) and not isinstance(value, (bool, np.bool_))
        x = float(value) if real else float("nan")
        if not (widget.min <= x <= widget.max and (x.is_integer() or not integer)):
            kind = "an integer" if integer else "a number"
            raise InputError(f"{name} must be {kind} between {number_text(widget.min)} and "
                             f"{number_text(widget.max)}, got {value!r}")
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
                raise InputError(f"{name}: numbers typed here must lie between {number_text(-TEXT_LIMIT)} "
                                 f"and {number_text(TEXT_LIMIT)}, got {tok}")
    return value


#: the largest magnitude of a number typed into a text field (refused by name, not overflowing)
TEXT_LIMIT = 1e6

#: between the groups of three digits of a long number: a narrow no-break space (a line never breaks there)
DIGIT_GROUP = "\u202f"


def number_text(x) -> str:
    """``x`` as a student reads it in a message: plain decimals, never ``1e+06``.

    Below a million, as ``:g`` writes it (every other number of the messages: ``-180``, ``0.05``,
    ``10000``); from a million on, where ``:g`` would write ``1e+06``, all the digits in groups of three
    (:data:`DIGIT_GROUP`); beyond 10¹⁵ or under 10⁻⁴, a power of ten written with superscripts.
    Negative numbers keep the ASCII minus, as every message does.

    Parameters
    ----------
    x : float

    Returns
    -------
    str

    Examples
    --------
    >>> [number_text(v) for v in (-180, 0.05, 10000, 123456.7, 2.5e16, 3e-7)]
    ['-180', '0.05', '10000', '123457', '2.5×10¹⁶', '3×10⁻⁷']
    >>> number_text(-1e6) == '-1' + DIGIT_GROUP + '000' + DIGIT_GROUP + '000'
    True
    """
    x = float(x)
    if not math.isfinite(x):
        return f"{x}"
    if x == 0:
        return "0"
    if abs(x) >= 1e15 or abs(x) < 1e-4:
        return power_text(x, 6)
    digits = max(0, 5 - math.floor(math.log10(abs(x))))
    text = f"{round(x, digits):.{digits}f}"
    if "." in text:
        text = text.rstrip("0").rstrip(".")
    sign, text = ("-", text[1:]) if text.startswith("-") else ("", text)
    whole, dot, frac = text.partition(".")
    if len(whole) > 6:
        whole = f"{int(whole):,}".replace(",", DIGIT_GROUP)
    return sign + whole + dot + frac


_NUMBER = re.compile(r"(?<![\w.])[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?(?![\w.])|"
                     r"(?<![\w])[-+]?(?:inf(?:inity)?|nan)(?![\w])", re.IGNORECASE)


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


def same_value(a, b) -> bool:
    try:
        return bool(a == b) or (a != a and b != b)
    except Exception:  # noqa: BLE001 - arrays and other odd values
        return a is b


def numeric_failure(exc: Exception) -> bool:
    """True for numpy's floating-point errors (overflow, invalid value) raised inside a computation."""
    if isinstance(exc, (FloatingPointError, OverflowError)):
        return True
    text = str(exc)
    return isinstance(exc, RuntimeWarning) and ("overflow" in text or "invalid value" in text)


def short_text(text: str) -> str:
    """``text`` on one line, whole (the picture wraps it onto lines of its width); a no-break space
    (between a number's digit groups, :func:`number_text`) is kept.

    >>> short_text("rod too short:\\n  l = 1")
    'rod too short: l = 1'
    """
    return " ".join(re.split(r"[ \t\n\r\f\v]+", str(text).strip(" \t\n\r\f\v")))


def shown_as(widget, value) -> tuple[str, str]:
    """``(name, value)`` of a control ``widget`` for a message ``f"{name} = {value}"``, as the student
    reads it: the name is the label without its unit; a number gets the unit, typed text its quotes,
    a checkbox on or off.

    Examples
    --------
    >>> shown_as(Step(-2, 2, 0.1, 1.0, "ω₁ (rad/s)").make("size1"), 0.0)
    ('ω₁', '0 rad/s')
    >>> shown_as(W.Text(description="joint speeds"), "1e6, 0")
    ('joint speeds', '“1e6, 0”')
    """
    label = " ".join(str(widget.description or "").split())
    if getattr(widget, "description_allow_html", False):       # the text the page shows
        label = html.unescape(re.sub(r"<[^>]*>", "", label))
    m = re.match(r"^(?P<name>.*?)\s*\((?P<unit>[^()]*)\)$", label)
    name, unit = (m["name"], m["unit"]) if m else (label, "")
    if isinstance(widget, W.Checkbox):
        return name, "on" if value else "off"
    if isinstance(widget, W.Text):
        return name, f"“{value}”"
    if isinstance(value, numbers.Real) and not isinstance(value, (bool, np.bool_)):
        unit = unit.replace(", ", " or ")
        return name, number_text(value) + ("" if not unit else unit if unit == "°" else f" {unit}")
    return name, str(value)


class ControlsMixin:
    """The controls of :class:`~planargeo.widgets.base.Explorer`: made, observed, echoes ignored."""

    def _make_controls(self, values: dict[str, Any]) -> None:
        """The controls (described as data or as widgets), the base's key and focus, the given values."""
        self.controls: dict[str, W.ValueWidget] = {k: make_control(k, c)
                                                   for k, c in dict(self.make_controls()).items()}
        bad = sorted(set(self.display_controls) - set(self.controls))
        if bad:  # a programming error in the subclass, not user input
            raise InputError(f"{type(self).__name__}.display_controls names no control {bad[0]!r}")
        extra = ["key"]
        focus = list(self.focus_options())
        if focus and "focus" not in self.controls:
            self.controls["focus"] = Choice(["all", *focus], "all", "focus").make("focus")
            extra.append("focus")
        if "key" not in self.controls:
            self.controls["key"] = Toggle(False, "key (legend)").make("key")
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
        """True for a slider's echo: ignore it (no update, no snapping to the grid)."""
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
        # every value set here may come back rounded: off the grid, to the grid's nearest value; on it,
        # in the page's own arithmetic (60 on a step of 5 from -180 came back as 59.99999999999997)
        if not from_front and isinstance(new, float) and math.isfinite(new):
            recent.append((now, new, _on_grid(new, widget.min, widget.step)))
            self._echo[name] = recent[-16:]
        return False

    @property
    def values(self) -> dict[str, Any]:
        """Current value of every control (a dragged value, not the slider's rounded echo of it)."""
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

    def _focus_follow(self, values: dict[str, Any]) -> dict[str, Any]:
        """``{"focus": "all"}`` when the focus chosen no longer exists for ``values`` (else nothing)."""
        if not self._base_focus or values.get("focus", "all") == "all":
            return {}
        try:
            options = ["all", *self.focus_options()]
        except Exception:  # noqa: BLE001 - options that cannot be listed: keep the choice
            return {}
        return {} if values["focus"] in options else {"focus": "all"}
